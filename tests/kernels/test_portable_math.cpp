// The bit-reproducible elementary functions against the C library's (which are accurate to
// within an ulp or so): they must agree to a few ulp over the ranges the step uses, and give
// the same bits in every SIMD width.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <xsimd/xsimd.hpp>

#include "kernels/portable_math.h"
#include "support/ulps.h"

namespace caskdem::kernels {
namespace {

using testing::ulps_apart;

TEST(PortableMath, ExpNegativeMatchesLibmToTwoUlp) {
  double worst = 0.0;
  for (int i = 0; i <= 400000; ++i) {
    const double x = 40.0 * i / 400000.0;
    worst = std::max(worst, ulps_apart(exp_negative(x), std::exp(-x)));
  }
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(exp_negative(0.0), 1.0);
  EXPECT_EQ(exp_negative(-3.0), 1.0);  // clamped: friction speeds are magnitudes
  EXPECT_NEAR(exp_negative(1e6), std::exp(-40.0), 1e-30);
}

TEST(PortableMath, SinCosMatchLibmToTwoUlpOnRotationRange) {
  double worst_sin = 0.0, worst_cos = 0.0, worst_abs = 0.0;
  for (int i = -200000; i <= 200000; ++i) {
    const double a = 4.0 * i / 200000.0;  // beyond +-pi/2, where a tipping cask stops
    const SinCos<double> r = sin_cos(a);
    if (std::abs(std::sin(a)) > 1e-3) worst_sin = std::max(worst_sin, ulps_apart(r.sin, std::sin(a)));
    if (std::abs(std::cos(a)) > 1e-3) worst_cos = std::max(worst_cos, ulps_apart(r.cos, std::cos(a)));
    worst_abs = std::max({worst_abs, std::abs(r.sin - std::sin(a)), std::abs(r.cos - std::cos(a))});
  }
  EXPECT_LE(worst_sin, 2.0);
  EXPECT_LE(worst_cos, 2.0);
  EXPECT_LE(worst_abs, 2.3e-16);
}

template <class Arch>
void expect_same_bits_as_scalar() {
  using Batch = xsimd::batch<double, Arch>;
  constexpr std::size_t width = Batch::size;
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), speed(0.0, 50.0);
  alignas(64) double input[width], wide_sin[width], wide_cos[width], wide_exp[width];
  for (int trial = 0; trial < 20000; ++trial) {
    for (std::size_t l = 0; l < width; ++l) input[l] = angle(random);
    const SinCos<Batch> r = sin_cos(Batch::load_aligned(input));
    r.sin.store_aligned(wide_sin);
    r.cos.store_aligned(wide_cos);
    for (std::size_t l = 0; l < width; ++l) {
      const SinCos<double> s = sin_cos(input[l]);
      ASSERT_EQ(std::memcmp(&s.sin, &wide_sin[l], sizeof(double)), 0);
      ASSERT_EQ(std::memcmp(&s.cos, &wide_cos[l], sizeof(double)), 0);
    }
    for (std::size_t l = 0; l < width; ++l) input[l] = speed(random);
    exp_negative(Batch::load_aligned(input)).store_aligned(wide_exp);
    for (std::size_t l = 0; l < width; ++l) {
      const double s = exp_negative(input[l]);
      ASSERT_EQ(std::memcmp(&s, &wide_exp[l], sizeof(double)), 0);
    }
  }
}

TEST(PortableMath, Sse2BatchGivesScalarBits) { expect_same_bits_as_scalar<xsimd::sse2>(); }

// sin_cos skips the argument reduction when every lane is within 0.75 rad (a rocking cask's
// range). One lane alone takes that branch; beside a lane at 3 rad it takes the reduction.
TEST(PortableMath, SinCosWithoutReductionGivesTheReductionsBits) {
  using Batch = xsimd::batch<double, xsimd::sse2>;
  std::vector<double> angles = {0.0, -0.0, 1e-300, -1e-300, 0.7499999999999999, -0.7499999999999999};
  for (int i = -100000; i <= 100000; ++i) angles.push_back(0.75 * i / 100000.0 * (1.0 - 1e-16));
  alignas(16) double input[2], wide_sin[2], wide_cos[2];
  for (double a : angles) {
    input[0] = a;
    input[1] = 3.0;
    const SinCos<Batch> reduced = sin_cos(Batch::load_aligned(input));
    reduced.sin.store_aligned(wide_sin);
    reduced.cos.store_aligned(wide_cos);
    const SinCos<double> direct = sin_cos(a);
    ASSERT_EQ(std::memcmp(&direct.sin, &wide_sin[0], sizeof(double)), 0) << a;
    ASSERT_EQ(std::memcmp(&direct.cos, &wide_cos[0], sizeof(double)), 0) << a;
  }
}

// lane::root_not_above lets the 3D step skip a square root (and the division after it) where
// every lane of a batch is decided from squares. It must never hide a root above its bound: at
// squares placed within a few ulp of the bound's square, across the range of magnitudes the
// contact forces and slides take, at the edges (zero, -0, subnormal, the underflow of the
// square, infinities, NaN), one lane at a time and in batches. And it must decide most
// clear cases, or it saves nothing.
TEST(PortableMath, RootNotAboveNeverHidesARootAboveItsBound) {
  std::mt19937_64 random(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double edges[] = {0.0, -0.0, 4.9e-324, 1e-310, 2.2250738585072014e-308, 1e-160, 1.5e-154, 1e-150,
                          1.0, 1e150, 1e300, HUGE_VAL, std::nan("")};
  std::vector<double> squares, bounds;
  for (double b : edges) {
    for (double q : edges) squares.push_back(q), bounds.push_back(b);
    squares.push_back(b * b), bounds.push_back(b);
  }
  long clear = 0, decided = 0;
  for (int i = 0; i < 400000; ++i) {
    const double bound = std::pow(10.0, -200.0 + 400.0 * unit(random)) * (unit(random) < 0.02 ? -1.0 : 1.0);
    double squared = bound * bound * (1.0 + std::ldexp(unit(random) - 0.5, -40 + static_cast<int>(40 * unit(random))));
    for (int k = static_cast<int>(8 * unit(random)) - 4; k != 0; k += k > 0 ? -1 : 1) {
      squared = std::nextafter(squared, k > 0 ? HUGE_VAL : 0.0);  // a few ulp either way
    }
    if (unit(random) < 0.2) squared = bound * bound * unit(random);  // clearly below
    squares.push_back(squared), bounds.push_back(bound);
  }
  for (std::size_t i = 0; i < squares.size(); ++i) {
    const bool above = std::sqrt(squares[i]) > bounds[i];
    const bool not_above = lane::root_not_above(squares[i], bounds[i]);
    ASSERT_FALSE(not_above && above) << "sqrt(" << squares[i] << ") against " << bounds[i];
    if (bounds[i] > 1e-150 && bounds[i] < 1e150 && squares[i] < 0.99 * bounds[i] * bounds[i]) {
      ++clear;
      decided += not_above;
    }
  }
  EXPECT_EQ(decided, clear) << "a clear case left to the root";
  EXPECT_GT(clear, 50000);
  using Wide = xsimd::batch<double, xsimd::sse2>;
  for (std::size_t i = 0; i + 2 <= squares.size(); i += 2) {
    const auto got = lane::root_not_above(Wide::load_unaligned(&squares[i]), Wide::load_unaligned(&bounds[i]));
    ASSERT_EQ(got.get(0), lane::root_not_above(squares[i], bounds[i]));
    ASSERT_EQ(got.get(1), lane::root_not_above(squares[i + 1], bounds[i + 1]));
  }
}

}  // namespace
}  // namespace caskdem::kernels
