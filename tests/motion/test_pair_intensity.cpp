// A station's components as one motion (motion/component_set.h) and the intensity measures of
// a horizontal pair (motion/pair_intensity.h). The readers against what the set's README
// states (every component's PGA to its four decimals, the time step, the tails that differ);
// RotD50 and RotD100 against closed forms: a pair in phase, x = A s(t) and y = B s(t), peaks
// at each angle at sqrt(A^2 + B^2) |cos(theta - phi)| max|s|, so RotD100 = sqrt(A^2 + B^2) max|s|
// and RotD50 = RotD100 / sqrt(2) (the median of |cos| over uniform angles is cos(pi/4)); a
// circular motion peaks at A at every angle; and the measures do not change when the sensors
// are turned.

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/units.h"
#include "motion/component_set.h"
#include "motion/pair_intensity.h"

namespace caskdem::motion {
namespace {

const std::filesystem::path sets = std::filesystem::path(CASKDEM_SHARED_DIR) / "motions" / "three-component";

struct StatedSet {
  std::string h1, h2, up;  // up empty: horizontals only
  double dt;
  std::size_t npts_h1, npts_h2, npts_up;
  double pga_h1, pga_h2, pga_up;  // g, as the README states them (four decimals)
};

// ../shared/motions/three-component/README.md, row by row.
const std::vector<StatedSet> stated = {
    {"elcentro1940_RSN6_H1_180.AT2", "elcentro1940_RSN6_H2_270.AT2", "elcentro1940_RSN6_UP.AT2", 0.01, 5372, 5346, 5378,
     0.2808, 0.2107, 0.1781},
    {"kobe1995_RSN1106_KJMA_H1_000.AT2", "kobe1995_RSN1106_KJMA_H2_090.AT2", "kobe1995_RSN1106_KJMA_UP.AT2", 0.02, 7500,
     7500, 7500, 0.8342, 0.6297, 0.3389},
    {"northridge1994_RSN1063_Rinaldi_H1_228.AT2", "northridge1994_RSN1063_Rinaldi_H2_318.AT2",
     "northridge1994_RSN1063_Rinaldi_UP.AT2", 0.01, 1991, 1991, 1991, 0.8741, 0.4723, 0.9582},
    {"lomaprieta1989_RSN753_Corralitos_H1_000.AT2", "lomaprieta1989_RSN753_Corralitos_H2_090.AT2",
     "lomaprieta1989_RSN753_Corralitos_UP.AT2", 0.005, 7997, 7999, 7999, 0.6447, 0.4828, 0.4578},
    {"sanfernando1971_RSN77_PacoimaDam_H1_164.AT2", "sanfernando1971_RSN77_PacoimaDam_H2_254.AT2",
     "sanfernando1971_RSN77_PacoimaDam_UP_DWN.AT2", 0.01, 4172, 4172, 4172, 1.2190, 1.2383, 0.6874},
    {"manjil1990_RSN1633_Abbar_H1_L.AT2", "manjil1990_RSN1633_Abbar_H2_T.AT2", "manjil1990_RSN1633_Abbar_UP_V.AT2", 0.02,
     2676, 2300, 2671, 0.5146, 0.4969, 0.5380},
    {"landers1992_RSN879_Lucerne_H1_260.AT2", "landers1992_RSN879_Lucerne_H2_345.AT2", "", 0.005, 9625, 9625, 0, 0.7252,
     0.7888, 0.0},
};

double pga_g(const Record& r) { return units::si_to_g(peak_ground_acceleration(r)); }

TEST(ComponentSets, EverySharedSetReadsWithItsStatedPgasOnOneTimeBase) {
  for (const StatedSet& s : stated) {
    const std::optional<std::filesystem::path> up = s.up.empty() ? std::nullopt : std::optional(sets / s.up);
    // Padded, so that each component's own peak is kept whatever its length.
    const ComponentSet padded = read_component_set(sets / s.h1, sets / s.h2, up, {}, TailRule::pad);
    EXPECT_NEAR(pga_g(padded.h1), s.pga_h1, 5e-5) << s.h1;
    EXPECT_NEAR(pga_g(padded.h2), s.pga_h2, 5e-5) << s.h2;
    if (up) {
      EXPECT_NEAR(pga_g(*padded.vertical), s.pga_up, 5e-5) << s.up;
    }
    const std::size_t longest = std::max({s.npts_h1, s.npts_h2, s.npts_up});
    std::size_t shortest = std::min(s.npts_h1, s.npts_h2);
    if (up) shortest = std::min(shortest, s.npts_up);
    const ComponentSet trimmed = read_component_set(sets / s.h1, sets / s.h2, up);
    for (const ComponentSet* set : {&padded, &trimmed}) {
      const std::size_t expected = set == &padded ? longest : shortest;
      EXPECT_EQ(set->h1.acceleration.size(), expected) << s.h1;
      EXPECT_EQ(set->h2.acceleration.size(), expected) << s.h2;
      EXPECT_DOUBLE_EQ(set->h1.time_step, s.dt);
      EXPECT_EQ(set->h2.time_step, set->h1.time_step);
      if (up) {
        EXPECT_EQ(set->vertical->acceleration.size(), expected);
        EXPECT_EQ(set->vertical->time_step, set->h1.time_step);
      }
      // The output says what was done exactly when the lengths differ.
      EXPECT_EQ(set->time_base.empty(), shortest == longest) << s.h1 << ": " << set->time_base;
    }
  }
}

TEST(ComponentSets, ComponentsSampledDifferentlyAreRefusedNamingBothFiles) {
  const std::filesystem::path kobe = sets / "kobe1995_RSN1106_KJMA_H1_000.AT2";  // dt 0.02
  const std::filesystem::path rinaldi = sets / "northridge1994_RSN1063_Rinaldi_H2_318.AT2";  // dt 0.01
  try {
    read_component_set(kobe, rinaldi, std::nullopt);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("Rinaldi_H2_318"), std::string::npos) << message;
    EXPECT_NE(message.find("KJMA_H1_000"), std::string::npos) << message;
  }
}

Record sampled(double dt, std::size_t n, auto f) {
  Record r;
  r.source = "closed form";
  r.time_step = dt;
  for (std::size_t i = 0; i < n; ++i) r.acceleration.push_back(f(dt * static_cast<double>(i)));
  return r;
}

// At 1-degree angles the strongest direction may fall between two: its peak is then read at
// most half a degree off, cos(0.5 deg) = 1 - 3.8e-5 of it.
constexpr double kAngleGrid = 4e-5;

TEST(PairIntensity, InPhasePairPeaksAtTheVectorSumAndItsMedianIsThatOverRootTwo) {
  const double omega = 2.0 * std::numbers::pi * 1.3;
  for (const auto& [a, b] : {std::pair{3.0, 4.0}, std::pair{1.0, 0.2}, std::pair{-2.0, 2.0}}) {
    // Sampled so that max |sin| = 1 is on a sample: peak of s exactly 1.
    const Record h1 = sampled(1.0 / (4.0 * 1.3 * 50.0), 2000, [&](double t) { return a * std::sin(omega * t); });
    const Record h2 = sampled(1.0 / (4.0 * 1.3 * 50.0), 2000, [&](double t) { return b * std::sin(omega * t); });
    const PairIntensity p = pair_intensity(h1, h2);
    const double vector_sum = std::hypot(a, b);
    EXPECT_NEAR(p.pga_rotd100, vector_sum, kAngleGrid * vector_sum) << a << ", " << b;
    EXPECT_LE(p.pga_rotd100, vector_sum * (1.0 + 1e-12));
    // The median of |cos(theta - phi)| over 180 angles a degree apart: the 90th and 91st peaks
    // lie at 45 deg -+ x from the strongest direction, x at most half a degree, and their mean
    // is cos(45 deg) cos(x): the same grid bound.
    EXPECT_NEAR(p.pga_rotd50, vector_sum / std::sqrt(2.0), kAngleGrid * vector_sum / std::sqrt(2.0)) << a << ", " << b;
    EXPECT_NEAR(p.pga_geometric_mean, std::sqrt(std::abs(a * b)), 1e-12 * vector_sum);
    const double direction = std::atan2(b, a) * 180.0 / std::numbers::pi;
    const double folded = std::fmod(direction + 180.0, 180.0);
    EXPECT_NEAR(std::min(std::abs(p.pga_rotd100_angle - folded), 180.0 - std::abs(p.pga_rotd100_angle - folded)), 0.0, 0.5)
        << a << ", " << b;
  }
}

TEST(PairIntensity, CircularMotionPeaksAtItsRadiusInEveryDirection) {
  const double radius = 2.5, omega = 2.0 * std::numbers::pi * 0.7;
  const double dt = 1e-4;
  const Record h1 = sampled(dt, 30000, [&](double t) { return radius * std::sin(omega * t); });
  const Record h2 = sampled(dt, 30000, [&](double t) { return radius * std::cos(omega * t); });
  const std::vector<double> peaks = rotated_peaks(h1.acceleration, h2.acceleration);
  // Sampling: the peak at an angle is read within omega dt / 2 of its phase, 1 - cos(2.2e-4).
  for (double peak : peaks) EXPECT_NEAR(peak, radius, 3e-8 * radius);
  const PairIntensity p = pair_intensity(h1, h2);
  EXPECT_NEAR(p.pga_rotd50, radius, 3e-8 * radius);
  EXPECT_NEAR(p.pga_rotd100, radius, 3e-8 * radius);
}

TEST(PairIntensity, TurningTheSensorsChangesNeitherRotD50NorRotD100) {
  const ComponentSet set = read_component_set(sets / "kobe1995_RSN1106_KJMA_H1_000.AT2",
                                              sets / "kobe1995_RSN1106_KJMA_H2_090.AT2", std::nullopt);
  const PairIntensity as_recorded = pair_intensity(set.h1, set.h2);
  EXPECT_GE(as_recorded.pga_rotd100, peak_ground_acceleration(set.h1) * (1.0 - 1e-15));
  EXPECT_GE(as_recorded.pga_rotd100, peak_ground_acceleration(set.h2) * (1.0 - 1e-15));
  EXPECT_LE(as_recorded.pga_rotd50, as_recorded.pga_rotd100);
  EXPECT_LE(as_recorded.pgv_rotd50, as_recorded.pgv_rotd100);
  // A whole number of degrees keeps the 1-degree grid: the same set of rotated peaks, reordered.
  for (double turn : {37.0, 90.0, 133.0}) {
    const double c = std::cos(turn * std::numbers::pi / 180.0), s = std::sin(turn * std::numbers::pi / 180.0);
    Record x = set.h1, y = set.h2;
    for (std::size_t i = 0; i < x.acceleration.size(); ++i) {
      x.acceleration[i] = c * set.h1.acceleration[i] + s * set.h2.acceleration[i];
      y.acceleration[i] = -s * set.h1.acceleration[i] + c * set.h2.acceleration[i];
    }
    const PairIntensity turned = pair_intensity(x, y);
    EXPECT_NEAR(turned.pga_rotd50, as_recorded.pga_rotd50, 1e-12 * as_recorded.pga_rotd50) << turn;
    EXPECT_NEAR(turned.pga_rotd100, as_recorded.pga_rotd100, 1e-12 * as_recorded.pga_rotd100) << turn;
    EXPECT_NEAR(turned.pgv_rotd50, as_recorded.pgv_rotd50, 1e-9 * as_recorded.pgv_rotd50) << turn;
    EXPECT_NEAR(turned.pgv_rotd100, as_recorded.pgv_rotd100, 1e-9 * as_recorded.pgv_rotd100) << turn;
  }
}

}  // namespace
}  // namespace caskdem::motion
