#include "diagnosis/synthesize.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/units.h"
#include "diagnosis/measured_set.h"
#include "diagnosis/measures.h"
#include "diagnosis/plan_report.h"
#include "diagnosis/test_simulation.h"
#include "ensemble/sampling.h"
#include "motion/synthetic.h"
#include "motion/table_motion.h"

namespace caskdem::diagnosis {

namespace {

constexpr double kSampleStep = 0.005;  // s: 200 Hz, a common data-logger rate
constexpr double kFreeTime = 2.5;      // s of recording after the motion

// How the diagnosis searches these data: fewer searches than its defaults, enough for them.
const char* kSearch = R"([diagnosis]
heldout = ["test2", "test5"]
starts = 6
evaluations = 50
seed = 1
)";

// Uniform in [low, high] from stream `what` of the seed.
double draw(std::uint64_t seed, std::uint64_t what, double low, double high) {
  return low + (high - low) * philox_uniform(seed, 0x5717 + what, 0, 0);
}

// Standard normal number for (test, sample, channel) of the seed (Box-Muller on Philox output).
double normal(std::uint64_t seed, std::uint64_t test, std::uint64_t sample, std::uint64_t channel) {
  return philox_normal(seed, {static_cast<std::uint32_t>(sample), static_cast<std::uint32_t>(test),
                              static_cast<std::uint32_t>(channel), 0x401e});
}

struct TestDesign {
  std::unique_ptr<motion::TableMotion> horizontal;
  std::unique_ptr<motion::TableMotion> vertical;
};

std::vector<TestDesign> designs(std::uint64_t seed, bool strong_vertical) {
  const double g = units::standard_gravity;
  auto sine = [&](double frequency, double acceleration, double cycles) {
    const double omega = 2.0 * std::numbers::pi * frequency;
    return motion::make_sine(acceleration / (omega * omega), frequency, cycles, 1.0);
  };
  auto earthquake = [&](std::uint64_t record_seed, double pga, double duration) {
    motion::SyntheticMotion s;
    s.seed = record_seed;
    s.duration = duration;
    s.time_step = kSampleStep;
    s.dominant_frequency = 4.0;  // a firm-soil 2.5 Hz prototype motion at 1/3 scale
    s.high_pass_frequency = 0.4;
    s.rise_time = 0.8;
    s.strong_duration = 2.0;
    s.decay = 1.0;
    s.pga = pga;
    return motion::make_record_motion(motion::synthetic_record(s));
  };
  // Kinds in pairs, so that the held-out tests (the 2nd and 5th) have training tests like them.
  std::vector<TestDesign> tests;
  tests.push_back({sine(1.5, 0.30 * g, 4.0), nullptr});
  tests.push_back({sine(2.5, 0.45 * g, 6.0), nullptr});
  tests.push_back({earthquake(seed * 100 + 11, 0.40 * g, 5.0), nullptr});
  tests.push_back({sine(2.0, 0.50 * g, 5.0), nullptr});
  tests.push_back({sine(1.2, 0.28 * g, 3.0), nullptr});
  tests.push_back({earthquake(seed * 100 + 12, 0.45 * g, 5.0), nullptr});
  tests.push_back({sine(3.0, 0.40 * g, 8.0), nullptr});
  tests.push_back({sine(2.0, 0.35 * g, 5.0), nullptr});
  for (std::size_t i = 0; i < tests.size(); ++i) {
    if (!strong_vertical) {
      tests[i].vertical = motion::make_still();  // the channel will carry sensor noise only
      continue;
    }
    const double pga = motion::peak_acceleration(*tests[i].horizontal, kSampleStep);
    const double ratio = draw(seed, 40 + i, 0.5, 0.7);
    tests[i].vertical = earthquake(seed * 100 + 50 + i, ratio * pga, tests[i].horizontal->duration() + kFreeTime);
  }
  return tests;
}

}  // namespace

std::string synthetic_specimen_text() {
  return R"(title = "Synthetic shaking-table tests of the 1/3 model cask"
# Made by `caskdem synthesize-measured`: what the experimenter knows, with nominal values.
# The true values and any hidden mechanism are in truth.json, which the diagnosis never reads.

[cask]
shape = "cylinder"
diameter = "0.95 m"
height = "2.033 m"
density = "8.743 g/cm^3"
half_width = "gyration"
rounding = "0.5 cm"

[contact]
normal_stiffness = "2.38e3 bar/cm"
shear_stiffness = "2.21e3 bar/cm"

[friction]
law = "constant"
coefficient = 0.35

[damping]
ratio = 0.03
frequency = "135 Hz"

[integration]
safety_factor = 0.05   # 5 times the paper's step, for speed; a test near a rocking bifurcation can change branch with it (docs/time-step.md)

)";
}

namespace {

// The true values: the specimen's baseline parameters off their nominal values, and each
// hidden mechanism at a value drawn from a range where its effect is visible.
std::vector<double> true_values(const ModelVariant& truth, std::uint64_t seed) {
  std::vector<double> x = truth.reference();
  const double sign = philox_uniform(seed, 0x5717, 1, 0) < 0.5 ? -1.0 : 1.0;
  for (std::size_t i = 0; i < truth.parameters().size(); ++i) {
    const Parameter& p = truth.parameters()[i];
    double& v = x[i];
    if (p.name == "friction") v = draw(seed, 1, 0.30, 0.40);
    else if (p.name == "damping_ratio") v = draw(seed, 2, 0.01, 0.05);
    else if (p.name == "stiffness_scale") v = draw(seed, 3, 0.7, 1.4);
    else if (p.name == "kinetic_ratio") v = draw(seed, 4, 0.55, 0.75);
    else if (p.name == "decay_speed") v = draw(seed, 5, 0.02, 0.10);
    else if (p.name == "impact_damping") v = draw(seed, 6, 8.0, 20.0);
    else if (p.name == "eccentricity") v = sign * draw(seed, 7, 0.4, 0.6) * p.high;
    else if (p.name == "base_camber") v = draw(seed, 8, 0.4, 0.8) * p.high;
    else if (p.name == "vertical_gain") v = 1.0;
    else if (p.name == "floor_soft_ratio") v = draw(seed, 9, 0.03, 0.10);
    else if (p.name == "floor_soft_depth") v = draw(seed, 10, 20.0, 50.0) * p.reference;
    else if (p.name == "wobble_damping") v = draw(seed, 11, 0.15, 0.30);
    else if (p.name == "sensor_delay") v = sign * draw(seed, 12, 0.03, 0.06);
  }
  return x;
}

// The true model's response to the table motion `clean` (noise-free), written as test NUMBER
// with the noise of (seed, number - 1, sample, channel).
void write_test(const std::filesystem::path& directory, int number, const std::string& description,
                const MeasuredTest& clean, const ModelVariant& truth, const std::vector<double>& x,
                const SyntheticSpec& spec) {
  const SimulatedHistory response =
      delayed(simulate_test(truth, clean, {x}, InstructionSet::automatic)[0], clean.time, truth.sensor_delay(x));
  const std::string name = "test" + std::to_string(number);
  const std::uint64_t i = static_cast<std::uint64_t>(number - 1);
  std::ofstream csv(directory / (name + ".csv"));
  csv << "# synthetic shaking-table test " << name << description << ": SI units, "
      << std::lround(1.0 / clean.time_step) << " Hz\n";
  csv << "t,table_acc,theta,slide,table_acc_v\n";
  const int decimals = time_decimals(clean.time_step);
  char line[256];
  for (std::size_t k = 0; k < clean.time.size(); ++k) {
    std::snprintf(line, sizeof line, "%.*f,%.9g,%.9g,%.9g,%.9g\n", decimals, clean.time[k],
                  clean.table_acceleration[k] + spec.table_noise * normal(spec.seed, i, k, 0),
                  response.rotation[k] + spec.rotation_noise * normal(spec.seed, i, k, 1),
                  response.slide[k] + spec.slide_noise * normal(spec.seed, i, k, 2),
                  clean.vertical_table_acceleration[k] + spec.table_noise * normal(spec.seed, i, k, 3));
    csv << line;
  }
}

// The specimen as the data were made: the stated one, as written (an edited specimen.toml states
// another model, not another cask), on the spec's normal law.
Case true_specimen(const std::filesystem::path& directory, const SyntheticSpec& spec) {
  Case specimen = read_specimen_text(synthetic_specimen_text() + kSearch, directory / "specimen.toml", nullptr);
  specimen.model.normal_law = spec.normal_law;
  return specimen;
}

}  // namespace

SyntheticTruth write_synthetic_measured_set(const std::filesystem::path& directory, const SyntheticSpec& spec) {
  std::filesystem::create_directories(directory);
  // Tests an earlier --drive added to a set here would be read as tests of this one.
  if (std::ifstream earlier(directory / "truth.json"); earlier) {
    const nlohmann::json old = nlohmann::json::parse(earlier, nullptr, false);
    if (old.is_object() && old.contains("added_tests") && old["added_tests"].is_array()) {
      for (const auto& name : old["added_tests"]) {
        if (name.is_string()) std::filesystem::remove(directory / (name.get<std::string>() + ".csv"));
      }
    }
  }
  std::ofstream(directory / "specimen.toml") << synthetic_specimen_text() << kSearch;
  const Case specimen = true_specimen(directory, spec);
  auto hidden = [&](Mechanism m) { return std::find(spec.hidden.begin(), spec.hidden.end(), m) != spec.hidden.end(); };
  const ModelVariant truth(specimen, spec.hidden, true);
  const std::vector<double> x = true_values(truth, spec.seed);
  std::vector<TestDesign> tests = designs(spec.seed, hidden(Mechanism::vertical_excitation));
  for (std::size_t i = 0; i < tests.size(); ++i) {
    MeasuredTest clean;
    clean.time_step = kSampleStep;
    clean.has_vertical = true;
    const auto samples = static_cast<std::size_t>(std::floor((tests[i].horizontal->duration() + kFreeTime) / kSampleStep)) + 1;
    for (std::size_t k = 0; k < samples; ++k) {
      const double t = k * kSampleStep;
      clean.time.push_back(t);
      clean.table_acceleration.push_back(tests[i].horizontal->acceleration(t));
      clean.vertical_table_acceleration.push_back(tests[i].vertical->acceleration(t));
    }
    write_test(directory, static_cast<int>(i) + 1, "", clean, truth, x, spec);
  }

  SyntheticTruth out;
  for (Mechanism m : truth.mechanisms()) out.hidden.push_back(mechanism_name(m));
  for (std::size_t i = 0; i < truth.parameters().size(); ++i) out.parameters.emplace_back(truth.parameters()[i].name, x[i]);
  nlohmann::json j;
  j["hidden"] = out.hidden;
  j["normal_law"] = normal_law_name(spec.normal_law);
  for (const auto& [name, value] : out.parameters) j["parameters"][name] = value;
  j["generator"] = "caskdem";
  j["seed"] = spec.seed;
  j["noise"] = {{"rotation_rad", spec.rotation_noise}, {"slide_m", spec.slide_noise}, {"table_m_s2", spec.table_noise}};
  std::ofstream(directory / "truth.json") << j.dump(2) << "\n";
  return out;
}

void add_synthetic_drive_test(const std::filesystem::path& directory, const SyntheticSpec& spec,
                              const std::filesystem::path& drive_file, int number) {
  const auto truth_file = directory / "truth.json";
  std::ifstream in(truth_file);
  if (!in) throw InputError(truth_file.string() + ": cannot be read; expected a set written by synthesize-measured");
  nlohmann::json j;
  SyntheticSpec same_noise = spec;  // the set's own noise levels
  std::vector<std::string> made_with;
  std::uint64_t made_seed = 0;
  std::string made_law;
  try {
    j = nlohmann::json::parse(in);
    if (j.value("generator", std::string("caskdem")) != "caskdem")
      throw InputError(truth_file.string() + ": the set was made by the \"" + j["generator"].get<std::string>() +
                       "\" generator; expected a set written by caskdem synthesize-measured");
    made_with = j.at("hidden").get<std::vector<std::string>>();
    made_seed = j.at("seed").get<std::uint64_t>();
    made_law = j.value("normal_law", std::string("linear"));
    same_noise.rotation_noise = j.at("noise").at("rotation_rad").get<double>();
    same_noise.slide_noise = j.at("noise").at("slide_m").get<double>();
    same_noise.table_noise = j.at("noise").at("table_m_s2").get<double>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(truth_file.string() + ": expected the truth.json synthesize-measured writes (" + e.what() + ")");
  }
  std::vector<std::string> hidden;
  for (Mechanism m : spec.hidden) hidden.push_back(mechanism_name(m));
  std::vector<std::string> made_sorted = made_with;
  std::sort(hidden.begin(), hidden.end());  // the set lists them in the model's order, --effect in the user's
  std::sort(made_sorted.begin(), made_sorted.end());
  if (made_seed != spec.seed || made_sorted != hidden || made_law != normal_law_name(spec.normal_law)) {
    throw InputError(truth_file.string() + ": the set was made with seed " + std::to_string(made_seed) + ", hidden " +
                     nlohmann::json(made_with).dump() + " and the " + made_law +
                     " normal law; expected the added test's seed, hidden mechanisms and normal law to be the set's");
  }
  const std::string name = "test" + std::to_string(number);
  if (number < 1 || std::filesystem::exists(directory / (name + ".csv"))) {
    throw InputError(directory.string() + ": expected a new test number, and " + name + " exists");
  }

  const TableDrive drive = read_drive(drive_file);
  MeasuredTest clean;
  clean.time_step = drive.time_step;
  clean.has_vertical = true;  // the table does not move vertically: the channel reads its noise
  for (std::size_t k = 0; k < drive.acceleration.size(); ++k) {
    clean.time.push_back(double(k) * drive.time_step);
    clean.table_acceleration.push_back(drive.acceleration[k]);
    clean.vertical_table_acceleration.push_back(0.0);
  }
  const Case specimen = true_specimen(directory, spec);
  const ModelVariant truth(specimen, spec.hidden, true);
  write_test(directory, number, " (" + drive.description + ")", clean, truth, true_values(truth, spec.seed), same_noise);
  j["added_tests"].push_back(name);
  std::ofstream(truth_file) << j.dump(2) << "\n";
}

}  // namespace caskdem::diagnosis
