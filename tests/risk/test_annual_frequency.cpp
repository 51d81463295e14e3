// The hazard-fragility convolution against closed forms it did not produce: a power-law hazard
// and a lognormal fragility (Cornell 1968; Kennedy and Ravindra 1984), a hazard quadratic in
// log-log space (the expectation of exp(-k1 x - k2 x^2) over a normal x), the epistemic
// fractiles of a power-law hazard, and the published HCLPF example.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/units.h"
#include "risk/annual_frequency.h"

namespace caskdem::risk {
namespace {

constexpr double g = units::standard_gravity;

// points log-spaced from `low` to `high` (in g), H(a) = hazard(a in g).
template <class Hazard>
HazardCurve curve_of(Hazard&& hazard, double low, double high, int points) {
  HazardCurve c;
  c.measure = {IntensityMeasure::Kind::pga, 0.0};
  for (int i = 0; i < points; ++i) {
    const double a = low * std::pow(high / low, double(i) / (points - 1));
    c.intensity.push_back(a * g);
    c.annual_frequency.push_back(hazard(a));
  }
  return c;
}

TEST(AnnualFrequency, PowerLawHazardMatchesTheClosedForm) {
  // H = k0 a^-k and F lognormal: lambda = H(A_m) exp(k^2 beta^2 / 2). Log-log interpolation
  // is exact for a power law and each segment's integral is in closed form: what is left is rounding.
  const double k0 = 1e-4, median = 0.9;
  for (double k : {1.0, 2.0, 3.0, 4.0}) {
    const HazardCurve h = curve_of([&](double a) { return k0 * std::pow(a, -k); }, 1e-3, 1e2, 26);
    for (double beta : {0.2, 0.3, 0.4, 0.5, 0.6}) {
      const double exact = k0 * std::pow(median, -k) * std::exp(k * k * beta * beta / 2.0);
      const FrequencyIntegral r = convolve(h, median * g, beta);
      EXPECT_NEAR(r.annual_frequency / exact, 1.0, 1e-8) << "k = " << k << ", beta = " << beta;
      // The disaggregation adds up to the whole.
      double parts = r.below_curve + r.above_curve;
      for (double s : r.segment_frequency) parts += s;
      EXPECT_NEAR(parts / r.annual_frequency, 1.0, 1e-14);
    }
  }
}

TEST(AnnualFrequency, CurvedHazardConvergesToTheClosedFormAsItsPointsGetDenser) {
  // H = k0 exp(-k1 x - k2 x^2), x = ln(a / 1 g): lambda = E[H(A)] over ln A ~ N(m, beta^2)
  // (integrating F |dH| by parts) = k0 exp((k1^2 beta^2 - 2 k1 m - 2 k2 m^2) / (2 s)) / sqrt(s),
  // s = 1 + 2 k2 beta^2. Log-log interpolation is exact only for k2 = 0: between points h
  // apart in x it lowers ln H by k2 (x - x_i)(x_i+1 - x), k2 h^2 / 6 on average, so lambda
  // comes out low by that fraction, falling 4 times per halving of h.
  const double k0 = 1e-4, k1 = 2.0, k2 = 0.25, beta = 0.45, m = std::log(0.7);
  const double s = 1.0 + 2.0 * k2 * beta * beta;
  const double exact = k0 * std::exp((k1 * k1 * beta * beta - 2.0 * k1 * m - 2.0 * k2 * m * m) / (2.0 * s)) / std::sqrt(s);
  const auto hazard = [&](double a) { return k0 * std::exp(-k1 * std::log(a) - k2 * std::log(a) * std::log(a)); };
  const double low = 0.02, high = 100.0;  // H rises below e^(-k1 / 2 k2) = 0.018 g
  for (int points : {21, 41, 81, 161}) {
    const double h = std::log(high / low) / (points - 1);
    const double error = convolve(curve_of(hazard, low, high, points), std::exp(m) * g, beta).annual_frequency / exact - 1.0;
    EXPECT_NEAR(error / (-k2 * h * h / 6.0), 1.0, 0.05) << points << " points: error " << error;
  }
}

TEST(AnnualFrequency, EpistemicFractilesOfAPowerLawHazardFollowTheClosedForm) {
  // With beta_U, ln lambda is normal with mean ln(H(A_m)) + k^2 beta_R^2 / 2 and standard
  // deviation k beta_U; the mean annual frequency is that of beta_C.
  const double k0 = 2e-4, k = 2.5, median = 1.1, beta_r = 0.3, beta_u = 0.35;
  const HazardCurve h = curve_of([&](double a) { return k0 * std::pow(a, -k); }, 1e-3, 1e2, 26);
  const SiteRisk r = site_risk(h, {median * g, beta_r, beta_u});
  const double at_median = k0 * std::pow(median, -k);
  const double median_frequency = at_median * std::exp(k * k * beta_r * beta_r / 2.0);
  EXPECT_NEAR(r.median / median_frequency, 1.0, 1e-8);
  EXPECT_NEAR(r.fractile_95 / (median_frequency * std::exp(1.6448536269514722 * k * beta_u)), 1.0, 1e-8);
  EXPECT_NEAR(r.fractile_05 / (median_frequency * std::exp(-1.6448536269514722 * k * beta_u)), 1.0, 1e-8);
  const double beta_c2 = beta_r * beta_r + beta_u * beta_u;
  EXPECT_NEAR(r.mean / (at_median * std::exp(k * k * beta_c2 / 2.0)), 1.0, 1e-8);
  EXPECT_GT(r.mean, r.median);  // the mean of a lognormal lies above its median
}

TEST(AnnualFrequency, HclpfOfThePublishedExample) {
  // A_m = 0.9 g, beta_R = 0.25, beta_U = 0.30: 0.3642 g by A_m exp(-1.645 (beta_R + beta_U))
  // and 0.3628 g as the 1 % point of the composite curve (as published, to 4 digits).
  const LognormalFragility f{0.9 * g, 0.25, 0.30};
  EXPECT_NEAR(hclpf_conservative(f) / g, 0.3642, 5e-5);
  EXPECT_NEAR(hclpf_composite(f) / g, 0.3628, 5e-5);
  // The composite definition is the 1 % point of the mean curve.
  EXPECT_NEAR(f.probability(hclpf_composite(f), 0.0), 0.01, 1e-12);
  // The conservative one is the 5 % point of the 95 % confidence curve.
  EXPECT_NEAR(f.probability(hclpf_conservative(f), 0.95), 0.05, 1e-12);
}

TEST(AnnualFrequency, ACurveThatStopsShortOfTheFragilityIsRefusedSayingWhereItMustReach) {
  const auto power = [](double a) { return 1e-4 * std::pow(a, -2.0); };
  const LognormalFragility f{0.9 * g, 0.4, 0.0};
  try {
    site_risk(curve_of(power, 1e-3, 1.0, 20), f);
    ADD_FAILURE() << "a curve ending at 1 g under a fragility of median 0.9 g was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("ends at 1 g"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("expected a curve reaching"), std::string::npos) << e.what();
  }
  try {
    site_risk(curve_of(power, 0.5, 100.0, 20), f);
    ADD_FAILURE() << "a curve starting at 0.5 g under a fragility of median 0.9 g was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("starts at 0.5 g"), std::string::npos) << e.what();
  }
  // Reaching to 5 g, where the fragility is near 1, the part above is settled.
  EXPECT_NO_THROW(site_risk(curve_of(power, 1e-2, 5.0, 20), f));
}

TEST(AnnualFrequency, ACurveWhoseContinuationOutgrowsTheFragilityIsRefusedNotANumber) {
  // Found by fuzzing: 3.1e4 per year at 0.01 g falling to 2.1e-7 at 0.0158 g, a log-log slope
  // of 56. Continued below 0.01 g it grows as e^(56 (x0 - x)), and F |dH| overflowed to
  // infinity times a cdf that underflowed to 0: the answer was NaN. Worked in logarithms the
  // integrand stays finite, its integral is still astronomical, and the curve is refused.
  HazardCurve c;
  c.measure = {IntensityMeasure::Kind::pga, 0.0};
  c.intensity = {0.01 * g, 0.0158 * g};
  c.annual_frequency = {3.130186e4, 2.097187e-07};
  const LognormalFragility f{std::sqrt(0.01 * 0.0158) * g, 0.4, 0.3};
  EXPECT_THROW(site_risk(c, f), std::invalid_argument);
  try {
    site_risk(c, f);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("expected a curve"), std::string::npos) << e.what();
  }
}

TEST(AnnualFrequency, ProbabilityInYearsAndAnnualFrequencyAreOneAnother) {
  // 10 % in 50 years is the 475-year return period of building codes.
  EXPECT_NEAR(1.0 / annual_frequency_from_probability(0.10, 50.0), 474.56, 0.01);
  for (double p : {1e-6, 0.02, 0.1, 0.5, 0.99}) {
    EXPECT_NEAR(probability_in_years(annual_frequency_from_probability(p, 50.0), 50.0) / p, 1.0, 1e-13);
  }
  EXPECT_THROW(annual_frequency_from_probability(1.0, 50.0), std::invalid_argument);
  EXPECT_THROW(annual_frequency_from_probability(0.1, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace caskdem::risk
