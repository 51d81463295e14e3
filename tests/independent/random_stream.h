#pragma once
// Reproducible random numbers: one std::mt19937_64 per (seed, stream), converted to doubles
// by hand (the standard's distributions may differ between library versions, so the same
// seed would not always give the same bytes).

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace independent {

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t stream)
      : engine_(seed * 0x9E3779B97F4A7C15ULL ^ (stream + 0x632BE59BD9B4E019ULL) * 0xBF58476D1CE4E5B9ULL) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  double normal() {  // Box-Muller
    const double u = 1.0 - uniform(), v = uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace independent
