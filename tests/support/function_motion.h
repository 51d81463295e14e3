#pragma once
// A table motion given by a function of time, for tests that need an exact, simple
// excitation (a ramp, a constant, a closed-form sine).

#include <functional>
#include <string>
#include <utility>

#include "motion/table_motion.h"

namespace caskdem::testing {

class FunctionMotion final : public motion::TableMotion {
 public:
  FunctionMotion(std::function<double(double)> acceleration, double duration)
      : acceleration_(std::move(acceleration)), duration_(duration) {}
  double acceleration(double t) const override { return acceleration_(t); }
  double velocity(double) const override { return 0.0; }
  double displacement(double) const override { return 0.0; }
  double duration() const override { return duration_; }
  std::string describe() const override { return "function"; }

 private:
  std::function<double(double)> acceleration_;
  double duration_;
};

}  // namespace caskdem::testing
