// Hazard-curve readers: the OpenQuake engine's CSV (the manual's example row), nshmp-haz's
// curves CSV and a plain table, checked against the numbers written into them and the
// Poisson conversion; one curve in all three forms gives one annual frequency; every refusal
// names the file, the line (and column) and what was expected.

#include <cmath>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/units.h"
#include "risk/annual_frequency.h"
#include "risk/hazard_curve.h"
#include "support/temporary_files.h"

namespace caskdem::risk {
namespace {

using caskdem::testing::input_error_of;
constexpr double g = units::standard_gravity;
constexpr const char* kOpenQuakeComment =
    "#,,,,,\"generated_by='OpenQuake engine 3.18.0', start_date='2023-10-03T06:09:08', checksum=2107362341, "
    "kind='mean', investigation_time=%YEARS%, imt='PGA'\"\n";

class HazardCurveFiles : public caskdem::testing::TemporaryFiles {
 protected:
  // One site's power-law curve H = 1e-4 a^-2.2 (a in g) at `levels`, as each form writes it.
  static double power(double a) { return 1e-4 * std::pow(a, -2.2); }
  std::vector<double> levels() const {
    std::vector<double> a;
    for (int i = 0; i <= 30; ++i) a.push_back(0.05 * std::pow(200.0, i / 30.0));  // 0.05 to 10 g
    return a;
  }
  std::string openquake(double years) const {
    std::string comment = kOpenQuakeComment;
    comment.replace(comment.find("%YEARS%"), 7, std::to_string(years));
    std::ostringstream text;
    text.precision(17);
    text << comment << "lon,lat,depth";
    for (double a : levels()) text << ",poe-" << a;
    text << "\n0.00000,0.00000,-0.10000";
    for (double a : levels()) text << "," << -std::expm1(-power(a) * years);
    text << "\n";
    return text.str();
  }
  std::string table() const {
    std::ostringstream text;
    text.precision(17);
    text << "# a synthetic site\nPGA [g], annual frequency\n";
    for (double a : levels()) text << a << ", " << power(a) << "\n";
    return text.str();
  }
  std::string nshmp(int sites) const {
    std::ostringstream text;
    text.precision(17);
    text << "lon,lat";
    for (double a : levels()) text << "," << a;
    for (int s = 0; s < sites; ++s) {
      text << "\n-122." << s << "0000,37.00000";
      for (double a : levels()) text << "," << power(a) * (s + 1);
    }
    text << "\n";
    return text.str();
  }
};

TEST_F(HazardCurveFiles, OpenQuakeManualExampleReadsAsAnnualFrequencies) {
  // The manual's first site: poe 0.4553861, 0.05754043, 0.006354517 at 0.1, 0.4, 0.6 g in 1 year.
  const auto file = write("hazard_curve-mean-PGA.csv",
                          std::string(kOpenQuakeComment).replace(std::string(kOpenQuakeComment).find("%YEARS%"), 7, "1.0") +
                              "lon,lat,depth,poe-0.1000000,poe-0.4000000,poe-0.6000000\n"
                              "0.00000,0.00000,-0.10000,4.553861E-01,5.754043E-02,6.354517E-03\n");
  const HazardCurve c = read_hazard_curve(file);
  EXPECT_EQ(intensity_measure_name(c.measure), "PGA");
  ASSERT_EQ(c.intensity.size(), 3u);
  EXPECT_DOUBLE_EQ(c.intensity[1], 0.4 * g);
  EXPECT_NEAR(c.annual_frequency[0], -std::log(1.0 - 0.4553861), 1e-15);
  EXPECT_NEAR(c.annual_frequency[2], -std::log(1.0 - 0.006354517), 1e-15);
}

TEST_F(HazardCurveFiles, OneCurveInEveryFormGivesOneAnnualFrequency) {
  // OpenQuake with a 50-year investigation time, nshmp-haz annual rates, and a table: the
  // same hazard, so the same risk (to the rounding of 17 digits through the Poisson law).
  std::filesystem::create_directories(dir_ / "PGA");
  const HazardCurve oq = read_hazard_curve(write("oq.csv", openquake(50.0)));
  const HazardCurve usgs = read_hazard_curve(write("PGA/total.csv", nshmp(1)));
  const HazardCurve plain = read_hazard_curve(write("site.csv", table()));
  const LognormalFragility f{0.9 * g, 0.4, 0.3};
  const double reference = site_risk(plain, f).mean;
  EXPECT_NEAR(reference / (1e-4 * std::pow(0.9, -2.2) * std::exp(2.2 * 2.2 * 0.25 / 2.0)), 1.0, 1e-8);
  EXPECT_NEAR(site_risk(oq, f).mean / reference, 1.0, 1e-10);
  EXPECT_NEAR(site_risk(usgs, f).mean / reference, 1.0, 1e-12);
  // A table of probabilities in 50 years, too.
  std::string poe = openquake(50.0);
  std::ostringstream t;
  t.precision(17);
  t << "PGA (g), poe in 50 years\n";
  for (double a : levels()) t << a << "\t" << -std::expm1(-power(a) * 50.0) << "\n";
  EXPECT_NEAR(site_risk(read_hazard_curve(write("poe.txt", t.str())), f).mean / reference, 1.0, 1e-10);
}

TEST_F(HazardCurveFiles, ASiteIsChosenFromAFileOfSeveral) {
  std::filesystem::create_directories(dir_ / "SA1P0");
  const auto file = write("SA1P0/curves.csv", nshmp(3));
  EXPECT_NE(input_error_of([&] { read_hazard_curve(file); }, "three sites, none chosen").find("holds 3 sites"),
            std::string::npos);
  HazardReadOptions options;
  options.site = std::pair{-122.2, 37.0};
  const HazardCurve c = read_hazard_curve(file, options);
  EXPECT_EQ(intensity_measure_name(c.measure), "SA(1)");
  EXPECT_NEAR(c.annual_frequency.front(), 3.0 * power(0.05), 1e-18);
  options.site = std::pair{-121.0, 37.0};
  EXPECT_NE(input_error_of([&] { read_hazard_curve(file, options); }, "a site not in the file").find("has no site at -121,37"),
            std::string::npos);
  options.site.reset();
  options.measure = parse_intensity_measure("PGA");
  EXPECT_NE(input_error_of([&] { read_hazard_curve(write("SA1P0/one.csv", nshmp(1)), options); }, "SA1P0 read as PGA")
                .find("is a curve of SA(1) but PGA was asked for"),
            std::string::npos);
}

TEST_F(HazardCurveFiles, AnAnnualProbabilityIsAProbabilityInOneYear) {
  const HazardCurve c = read_hazard_curve(write("p.csv", "PGA [g], annual probability of exceedance\n0.1, 0.5\n0.2, 0.01\n"));
  EXPECT_NEAR(c.annual_frequency[0], std::log(2.0), 1e-15);
  EXPECT_NEAR(c.annual_frequency[1], -std::log(0.99), 1e-15);
  // A rise within rounding is read as flat, so the stored curve never rises.
  const HazardCurve flat = read_hazard_curve(write("f.csv", "PGA [g], annual frequency\n0.1, 1e-3\n0.2, 1.0000000001e-3\n0.3, 1e-4\n"));
  EXPECT_EQ(flat.annual_frequency[1], flat.annual_frequency[0]);
  EXPECT_NO_THROW(check_hazard_curve(flat));
}

TEST_F(HazardCurveFiles, ZerosAtTheTopEndTheCurve) {
  const HazardCurve c = read_hazard_curve(write("z.csv", "PGA [g], annual frequency\n0.1, 1e-3\n0.2, 2e-4\n0.4, 0\n0.8, 0\n"));
  EXPECT_EQ(c.intensity.size(), 2u);
  EXPECT_TRUE(c.cut_at_zero);
}

TEST_F(HazardCurveFiles, EveryBadCurveIsRefusedNamingTheLineAndWhatWasExpected) {
  struct Case {
    const char* what;
    std::string text;
    std::string message;
  };
  const std::string header = "PGA [g], annual frequency\n";
  const std::string oq_header = std::string(kOpenQuakeComment).replace(std::string(kOpenQuakeComment).find("%YEARS%"), 7, "50");
  const Case cases[] = {
      {"a rise", header + "0.1, 1e-3\n0.2, 2e-3\n", "bad.csv:3: the hazard rises from 0.001 to 0.002 per year"},
      {"a positive value after a zero", header + "0.1, 1e-3\n0.2, 0\n0.3, 1e-5\n", "bad.csv:4: the hazard rises from 0"},
      {"intensities not increasing", header + "0.2, 1e-3\n0.1, 1e-4\n", "bad.csv:3: intensity 0.1 g after 0.2 g; expected intensities increasing"},
      {"a negative intensity", header + "-0.1, 1e-3\n0.1, 1e-4\n", "bad.csv:2: intensity -0.1 g; expected a finite value above 0"},
      {"a probability of 1", oq_header + "lon,lat,depth,poe-0.1,poe-0.2\n0,0,0,1.0,0.5\n",
       "bad.csv:3: column poe-0.1: probability of exceedance 1 in 50 years is an infinite annual frequency"},
      {"a probability above 1", oq_header + "lon,lat,depth,poe-0.1,poe-0.2\n0,0,0,1.5,0.5\n",
       "bad.csv:3: column poe-0.1: probability of exceedance 1.5 in 50 years; expected a probability below 1"},
      {"a rise in OpenQuake", oq_header + "lon,lat,depth,poe-0.1,poe-0.2\n0,0,0,0.1,0.5\n",
       "bad.csv:3: column poe-0.2: the hazard rises"},
      {"no unit", "PGA, annual frequency\n0.1, 1e-3\n0.2, 1e-4\n", "bad.csv:1: first column \"PGA\"; expected the intensity measure and its unit"},
      {"a unit of another dimension", "PGA [cm/s], annual frequency\n0.1, 1e-3\n0.2, 1e-4\n", "bad.csv:1: unit \"cm/s\" of PGA"},
      {"an unknown measure", "PGD [cm], annual frequency\n0.1, 1e-3\n0.2, 1e-4\n", "bad.csv:1: first column \"PGD [cm]\""},
      {"probabilities without years", "PGA [g], poe\n0.1, 1e-3\n0.2, 1e-4\n", "bad.csv:1: second column \"poe\" holds probabilities"},
      {"an unknown second column", "PGA [g], hazard\n0.1, 1e-3\n0.2, 1e-4\n", "bad.csv:1: second column \"hazard\""},
      {"a word for a number", header + "0.1, 1e-3\n0.2, high\n", "bad.csv:3: expected two numbers"},
      {"one point", header + "0.1, 1e-3\n", "bad.csv:2: has 1 point(s) with a non-zero hazard"},
      {"OpenQuake without investigation_time", "# imt='PGA'\nlon,lat,depth,poe-0.1\n",
       "bad.csv:1: expected the OpenQuake header comment with investigation_time"},
      {"nshmp-haz outside its folder", "lon,lat,0.1,0.2\n0,0,1e-3,1e-4\n", "does not say its intensity measure"},
      {"a short row", oq_header + "lon,lat,depth,poe-0.1,poe-0.2\n0,0,0,0.1\n", "bad.csv:3: has 4 values; expected 5"},
  };
  for (const Case& c : cases) {
    const auto file = write("bad.csv", c.text);
    const std::string message = input_error_of([&] { read_hazard_curve(file); }, c.what);
    EXPECT_NE(message.find(c.message), std::string::npos) << c.what << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << c.what << ": one line";
  }
}

TEST(IntensityMeasureNames, TheFormsHazardCodesWrite) {
  EXPECT_EQ(intensity_measure_name(*parse_intensity_measure("SA(0.2)")), "SA(0.2)");
  EXPECT_EQ(intensity_measure_name(*parse_intensity_measure("sa(1.0 s)")), "SA(1)");
  EXPECT_EQ(intensity_measure_name(*parse_intensity_measure("SA0P2")), "SA(0.2)");
  EXPECT_EQ(intensity_measure_name(*parse_intensity_measure("pgv")), "PGV");
  EXPECT_FALSE(parse_intensity_measure("SA(0)"));
  EXPECT_FALSE(parse_intensity_measure("PGD"));
  EXPECT_TRUE(*parse_intensity_measure("SA(1.0)") == *parse_intensity_measure("SA1P0"));
  EXPECT_FALSE(*parse_intensity_measure("SA(1.0)") == *parse_intensity_measure("SA(0.2)"));
}

}  // namespace
}  // namespace caskdem::risk
