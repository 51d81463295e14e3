// Tests of the independent generator against what it did not produce: the statics of a
// Hunt-Crossley (Winkler for n = 1) circular footprint, the rocking onset a = g tan(alpha)
// and Housner's (1963) free rocking of a rigid block, energy conservation, reproducibility,
// and that each hidden effect shows in the data.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "cylinder_model.h"
#include "excitation.h"
#include "measured_set.h"
#include "simulate.h"

namespace independent {
namespace {

CaskParameters nominal(double stiffness_scale = 1.0, double zeta = 0.03) {
  CaskParameters p;
  set_standing_stiffness(p, stiffness_scale * kNominalStiffness, zeta);
  return p;
}

std::vector<double> grid(double end, double step) {
  std::vector<double> t;
  for (double x = step; x <= end + 1e-12; x += step) t.push_back(x);
  return t;
}

// Static settlement: k_h d^n pi r^2 = m g for a flat base.
TEST(Statics, SettlementMatchesTheFootprintIntegral) {
  const CaskParameters p = nominal();
  const CylinderModel model(p);
  const State rest = model.equilibrium();
  const double settlement = p.half_height - rest[1];
  const double expected = std::pow(p.mass() * p.gravity / (std::numbers::pi * p.radius * p.radius * p.k_h), 1.0 / 1.5);
  std::printf("settlement %.6e m, closed form %.6e m, relative error %.2e\n", settlement, expected,
              settlement / expected - 1.0);
  EXPECT_NEAR(settlement / expected, 1.0, 1e-9);
  EXPECT_NEAR(rest[2], 0.0, 1e-12);
}

// Tilt under a couple M below uplift: the footprint's rotational stiffness is the pressure's
// slope at the settlement times the disc's second moment, K = n k_h d^(n-1) pi r^4 / 4.
TEST(Statics, TiltUnderACoupleMatchesTheRotationalStiffness) {
  const CaskParameters p = nominal();
  const CylinderModel model(p);
  const double d = p.half_height - model.equilibrium()[1];
  const double stiffness = 1.5 * p.k_h * std::sqrt(d) * std::numbers::pi * std::pow(p.radius, 4) / 4.0;
  const double moment = 0.05 * stiffness * d / p.radius;  // rim moves 5% of the settlement
  const double tilt = model.equilibrium(moment)[2];
  std::printf("tilt %.6e rad, M/K %.6e rad, relative error %.2e\n", tilt, moment / stiffness, tilt * stiffness / moment - 1.0);
  EXPECT_NEAR(tilt * stiffness / moment, 1.0, 2e-3);
}

// Under a slow ramp of table acceleration with friction that holds, the cask starts to rock
// when the inertial moment m a h exceeds the weight's m g r about the rim: a = g tan(alpha).
// Stiff contact (x1000), so that the footprint's elastic tilt near the limit stays below the
// 1e-3 rad that marks rocking; a smooth rise to 0.9 g tan(alpha), then 0.01 g/s.
TEST(Rocking, OnsetUnderASlowRampIsAtGTanAlpha) {
  CaskParameters p = nominal(1000.0, 0.2);
  p.mu_static = 1.0;
  const CylinderModel model(p);
  const double critical = p.gravity * std::tan(p.slenderness()), rate = 0.01 * p.gravity, rise = 1.5;
  auto acceleration = [=](double t) {
    const double u = std::min(t / rise, 1.0);
    return 0.9 * critical * u * u * (3.0 - 2.0 * u) + rate * std::max(t - rise, 0.0);
  };
  const auto times = grid(8.0, 1e-3);
  const Response r = simulate(model, {acceleration, nullptr}, model.equilibrium(), times);
  double onset = -1.0;
  for (std::size_t k = 0; k < times.size(); ++k)
    if (std::abs(r.rotation[k]) > 1e-3) {
      onset = acceleration(times[k]);
      break;
    }
  std::printf("rocking (1e-3 rad) at %.4f m/s^2, g tan(alpha) %.4f m/s^2, relative error %.2e\n", onset, critical,
              onset / critical - 1.0);
  ASSERT_GT(onset, 0.0);
  EXPECT_GE(onset / critical, 0.995);
  EXPECT_LE(onset / critical, 1.02);
}

// The rigid block's time from release at theta0 to the first impact (a quarter period):
// energy, (1/2) I_O theta'^2 = m g R [cos(alpha - theta0) - cos(alpha - theta)], integrated
// with theta = theta0 (1 - u^2), which removes the square-root singularity at release.
double housner_quarter_period(const CaskParameters& p, double theta0) {
  const double alpha = p.slenderness(), p2 = p.housner_frequency() * p.housner_frequency();
  auto f = [&](double u) {
    if (u == 0.0) return 2.0 * theta0 / std::sqrt(2.0 * p2 * theta0 * std::sin(alpha - theta0));
    const double th = theta0 * (1.0 - u * u);
    return 2.0 * theta0 * u / std::sqrt(2.0 * p2 * (std::cos(alpha - theta0) - std::cos(alpha - th)));
  };
  const int n = 4000;  // Simpson
  double s = f(0.0) + f(1.0);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(static_cast<double>(i) / n);
  return s / (3.0 * n);
}

struct FreeRocking {
  double first_impact = -1.0;   // s
  double second_amplitude = 0;  // rad, peak after the first impact
};

FreeRocking release(const CaskParameters& p, double theta0) {
  const CylinderModel model(p);
  // Resting on the rim at theta0 (the rim at x = -r touching the floor), at rest.
  State s{0.0, p.radius * std::sin(theta0) + p.half_height * std::cos(theta0), theta0, 0.0, 0.0, 0.0};
  const auto times = grid(1.6, 1e-4);
  const Response r = simulate(model, {}, s, times);
  FreeRocking out;
  for (std::size_t k = 1; k < times.size(); ++k) {
    if (out.first_impact < 0.0 && r.rotation[k] <= 0.0) {
      out.first_impact = times[k - 1] + 1e-4 * r.rotation[k - 1] / (r.rotation[k - 1] - r.rotation[k]);
    }
    if (out.first_impact > 0.0) out.second_amplitude = std::max(out.second_amplitude, -r.rotation[k]);
  }
  return out;
}

// In the stiff limit (stiffness x100) the cylinder rocks as Housner's rigid block until it
// lands: the time to the first impact is the rigid block's. The landing's loss depends on the
// contact: with a critically damped footprint the effective restitution (from Housner's
// amplitude relation) lies between Housner's e (a plastic landing on the new rim alone) and
// 1; a distributed footprint loses less than Housner's e, as measured restitutions do
// (rocking-theory note: 0.963 measured on the 1/3 model).
TEST(Rocking, FreeRockingInTheStiffLimitFollowsHousner) {
  CaskParameters p = nominal(100.0, 0.0);
  p.mu_static = 1.0;
  const double alpha = p.slenderness(), theta0 = 0.3 * alpha;
  const FreeRocking elastic = release(p, theta0);
  const double expected = housner_quarter_period(p, theta0);
  std::printf("first impact at %.5f s, rigid block %.5f s, relative error %.2e\n", elastic.first_impact, expected,
              elastic.first_impact / expected - 1.0);
  EXPECT_NEAR(elastic.first_impact / expected, 1.0, 0.005);

  // cos(alpha - theta1) - cos alpha = e^2 [cos(alpha - theta0) - cos alpha].
  const double housner_e = 1.0 - 2.0 * p.mass() * p.radius * p.radius / p.pivot_inertia();
  CaskParameters damped = p;
  set_standing_stiffness(damped, 100.0 * kNominalStiffness, 1.0);
  const FreeRocking plastic = release(damped, theta0);
  const double e = std::sqrt((std::cos(alpha - plastic.second_amplitude) - std::cos(alpha)) /
                             (std::cos(alpha - theta0) - std::cos(alpha)));
  std::printf("after the first impact: %.4f rad (undamped %.4f), restitution %.3f, Housner's %.3f\n",
              plastic.second_amplitude, elastic.second_amplitude, e, housner_e);
  EXPECT_GT(e, housner_e);
  EXPECT_LT(e, 1.0);
}

// With no damping, no friction and no excitation the total energy is constant: its drift
// measures the integrator's error.
TEST(Energy, ConservedInFreeVibrationWithoutLosses) {
  CaskParameters p = nominal(1.0, 0.0);
  p.mu_static = 0.0;
  const CylinderModel model(p);
  State s = model.equilibrium();
  s[2] += 0.01;  // tilted: it lands on its rim and rocks
  s[1] += p.radius * 0.01;
  const double e0 = model.energy(s);
  const double excess = e0 - model.energy(model.equilibrium());
  const auto times = grid(1.0, 1e-3);
  const Response r = simulate(model, {}, s, times);
  double worst = 0.0;
  for (const State& x : r.states) worst = std::max(worst, std::abs(model.energy(x) - e0));
  std::printf("energy drift over 1 s: %.3e J of %.3e J above rest (%.2e)\n", worst, excess, worst / excess);
  EXPECT_LT(worst / excess, 1e-3);
}

std::string slurp(const std::filesystem::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::filesystem::path scratch(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("independent_generator_" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  return dir;
}

MeasuredSetOptions one_test() {
  MeasuredSetOptions o;
  o.tests = {4};  // the 5 Hz sine: it rocks and slides
  o.free_time = 1.0;
  return o;
}

TEST(MeasuredSet, SameSeedGivesTheSameBytes) {
  const auto a = scratch("a"), b = scratch("b"), c = scratch("c");
  write_independent_measured_set(a, "eccentric_mass", 3, one_test());
  write_independent_measured_set(b, "eccentric_mass", 3, one_test());
  write_independent_measured_set(c, "eccentric_mass", 4, one_test());
  for (const char* f : {"specimen.toml", "test4.csv", "truth.json"}) EXPECT_EQ(slurp(a / f), slurp(b / f)) << f;
  EXPECT_NE(slurp(a / "test4.csv"), slurp(c / "test4.csv"));
  EXPECT_NE(slurp(a / "specimen.toml").find("footprint = \"distributed\""), std::string::npos);
}

// Largest difference of each column of two CSV files of the same test.
std::vector<double> column_differences(const std::filesystem::path& x, const std::filesystem::path& y) {
  std::ifstream a(x), b(y);
  std::string la, lb;
  std::vector<double> worst(5, 0.0);
  while (std::getline(a, la) && std::getline(b, lb)) {
    if (la.empty() || !std::isdigit(static_cast<unsigned char>(la[0]))) continue;
    std::stringstream sa(la), sb(lb);
    std::string fa, fb;
    for (int c = 0; c < 5 && std::getline(sa, fa, ',') && std::getline(sb, fb, ','); ++c)
      worst[c] = std::max(worst[c], std::abs(std::stod(fa) - std::stod(fb)));
  }
  return worst;
}

TEST(MeasuredSet, EachEffectChangesTheData) {
  const auto null = scratch("none");
  const auto base = write_independent_measured_set(null, "none", 2, one_test());
  EXPECT_FALSE(base.tests[0].tipped_over);
  EXPECT_GT(base.tests[0].peak_rotation, 5e-3);  // the null rocks
  for (const std::string& effect : effect_names()) {
    const auto dir = scratch(effect);
    write_independent_measured_set(dir, effect, 2, one_test());
    const auto d = column_differences(null / "test4.csv", dir / "test4.csv");
    std::printf("%-32s max |d theta| %.2e rad  |d slide| %.2e m  |d table_acc_v| %.2e m/s^2\n", effect.c_str(), d[2],
                d[3], d[4]);
    // Above the sensors' noise (2e-4 rad, 1e-4 m), which is the same in both: well above it,
    // except for the Stribeck law, which acts only while the base slips, and the base slips
    // about a millimetre in these tests.
    const double factor = effect == "velocity_dependent_friction" ? 1.0 : 10.0;
    EXPECT_TRUE(d[2] > factor * 2e-4 || d[3] > factor * 1e-4) << effect;
    EXPECT_EQ(d[1], 0.0) << effect;  // the horizontal input is the test's, not the effect's
  }
}

// A drive file as caskdem plan-test writes it: the 5 Hz sine of test4 sampled at 200 Hz.
std::filesystem::path write_sine_drive(const std::filesystem::path& file, double record_time) {
  const auto sine = ramped_sine(0.010, 5.0, 6.0);
  std::ofstream out(file);
  out << "# proposed test 1: sine 5 Hz, 10 mm\n# the table drive, noise-free\nt,table_acc\n";
  char line[64];
  for (int k = 0; k * 0.005 <= record_time + 1e-9; ++k) {
    std::snprintf(line, sizeof line, "%.6f,%.9g\n", k * 0.005, sine(k * 0.005));
    out << line;
  }
  return file;
}

// A test added from a drive file is the programme's test when the drive is that test's table
// motion: the same cask (same effect and seed), the same recording. The drive is the sine's
// samples joined by straight lines, which differ from the sine by at most (omega h)^2 / 8 =
// 0.8 % of its peak at 5 Hz and 200 Hz; the response may differ by about as much.
TEST(MeasuredSet, ATestAddedFromItsOwnDriveMatchesTheProgrammesTest) {
  const auto dir = scratch("drive");
  const MeasuredSetOptions options = one_test();
  const auto set = write_independent_measured_set(dir, "eccentric_mass", 5, options);
  const double record_time = ramped_sine_duration(5.0, 6.0) + options.free_time;
  const auto drive = write_sine_drive(dir / "drive.csv", record_time);
  const TestSummary added = add_drive_test(dir, "eccentric_mass", 5, drive, 7);
  const TestSummary& own = set.tests[0];
  std::printf("programme test4: peak rotation %.5f rad, peak slide %.3f mm; from the drive: %.5f rad, %.3f mm\n",
              own.peak_rotation, 1e3 * own.peak_slide, added.peak_rotation, 1e3 * added.peak_slide);
  EXPECT_EQ(added.name, "test7");
  EXPECT_NEAR(added.peak_rotation, own.peak_rotation, 0.01 * own.peak_rotation);
  EXPECT_NEAR(added.peak_slide, own.peak_slide, 0.02 * own.peak_slide + 1e-5);
  // The same recording length, and the table channel is the drive plus the set's noise.
  std::ifstream a(dir / "test4.csv"), b(dir / "test7.csv");
  const auto rows = [](std::ifstream& in) {
    std::string line;
    int n = 0;
    while (std::getline(in, line)) n += !line.empty() && std::isdigit(static_cast<unsigned char>(line[0]));
    return n;
  };
  EXPECT_EQ(rows(a), rows(b));
  const auto d = column_differences(dir / "test4.csv", dir / "test7.csv");
  EXPECT_LT(d[1], 10 * 0.003 + 0.008 * 9.87);  // two noise draws (0.003 m/s^2 each) and the interpolation
  // truth.json lists the added test; written again, the set is its own tests alone.
  EXPECT_NE(slurp(dir / "truth.json").find("\"test7\""), std::string::npos);
  write_independent_measured_set(dir, "eccentric_mass", 5, options);
  EXPECT_FALSE(std::filesystem::exists(dir / "test7.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "test4.csv"));
}

TEST(MeasuredSet, ABadDriveIsRefusedNamingTheFileAndLine) {
  const auto dir = scratch("bad-drive");
  write_independent_measured_set(dir, "none", 2, one_test());
  std::ofstream(dir / "uneven.csv") << "t,table_acc\n0,0\n0.005,1\n0.011,2\n";
  std::ofstream(dir / "header.csv") << "time,acc\n0,0\n";
  const auto message = [&](auto&& call) {
    try {
      call();
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([&] { add_drive_test(dir, "none", 2, dir / "uneven.csv", 7); }).find("uneven.csv: line 4"),
            std::string::npos);
  EXPECT_NE(message([&] { add_drive_test(dir, "none", 2, dir / "header.csv", 7); }).find("header.csv: line 1"),
            std::string::npos);
  const auto drive = write_sine_drive(dir / "drive.csv", 1.0);
  EXPECT_NE(message([&] { add_drive_test(dir, "none", 3, drive, 7); }).find("the same"), std::string::npos);
  EXPECT_NE(message([&] { add_drive_test(dir, "none", 2, drive, 4); }).find("already exists"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "test7.csv"));
}

TEST(Cli, BadArgumentsExitWithTwo) {
  const std::string bin = INDEPENDENT_DATA_BINARY;
  const auto out = scratch("cli").string();
  auto run = [&](const std::string& args) { return WEXITSTATUS(std::system((bin + " " + args + " 2>/dev/null").c_str())); };
  EXPECT_EQ(run("--out " + out + " --effect friction --seed 1"), 2);
  EXPECT_EQ(run("--out " + out + " --effect none --seed -1"), 2);
  EXPECT_EQ(run("--out " + out + " --effect none --seed 1 --footprint wide"), 2);
  EXPECT_EQ(run("--effect none --seed 1"), 2);
  EXPECT_EQ(run("--out " + out + " --effect none --seed 1 --extra"), 2);
  EXPECT_EQ(run("--out " + out + " --effect none --seed 1 --drive d.csv"), 2);  // no --test
  EXPECT_EQ(run("--out " + out + " --effect none --seed 1 --drive d.csv --test 0"), 2);
  EXPECT_EQ(run("--out " + out + " --effect none --seed 1 --drive d.csv --test 7"), 2);  // no set there
  EXPECT_EQ(run("--out " + out + " --effect none --seed 1 --footprint radius --drive d.csv --test 7"), 2);  // the set's own
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace independent
