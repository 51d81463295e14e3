#pragma once
// Distributions of the uncertain parameters, sampled by inverse transform of a uniform
// number in (0, 1): x = F^-1(u). Truncation [low, high] maps u into [F(low), F(high)].
//
//   constant   value
//   uniform    low, high
//   normal     mean, std            (optionally truncated to [low, high])
//   lognormal  median, log_std      (ln x normal with mean ln median; optionally truncated)

#include <limits>
#include <string>

namespace caskdem {

struct Distribution {
  enum class Kind { constant, uniform, normal, lognormal };
  Kind kind = Kind::constant;
  double first = 0.0;   // value | low | mean | median
  double second = 0.0;  // -     | high | std  | log_std
  double low = -std::numeric_limits<double>::infinity();   // truncation (normal, lognormal)
  double high = std::numeric_limits<double>::infinity();

  double quantile(double u) const;  // u in (0, 1)
  double truncation_mass() const;   // probability of [low, high] under the untruncated normal or lognormal; else 1
  double lowest() const;            // smallest value the distribution can give
  double highest() const;
  std::string describe() const;
};

}  // namespace caskdem
