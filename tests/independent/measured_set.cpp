#include "measured_set.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "excitation.h"
#include "random_stream.h"
#include "simulate.h"

#ifndef INDEPENDENT_MOTIONS_DIR
#define INDEPENDENT_MOTIONS_DIR "../shared/motions"
#endif

namespace independent {

namespace {

constexpr double kSampleStep = 0.005;                 // s: 200 Hz
const double kTimeFactor = 1.0 / std::sqrt(3.0);      // 1/3-scale similitude
constexpr double kSineAmplitude = 0.010;              // m
constexpr double kG = 9.80665;

struct Design {
  std::string description;
  std::function<double(double)> horizontal, vertical_shape;  // vertical_shape: peak 1 x horizontal peak
  double duration = 0.0;
};

struct Earthquake {
  const char* label;
  const char* horizontal;
  const char* vertical;
  double start, end;  // prototype window, s
  double pga;         // model peak, in g
};

Design sine_design(double frequency, double cycles) {
  Design d;
  d.description = "sine " + std::to_string(frequency).substr(0, 3) + " Hz, 10 mm";
  d.horizontal = ramped_sine(kSineAmplitude, frequency, cycles);
  // The vertical actuator runs the same frequency a quarter cycle behind, at unit peak ratio.
  d.vertical_shape = ramped_sine(kSineAmplitude, frequency, cycles, 0.5 * std::numbers::pi);
  d.duration = ramped_sine_duration(frequency, cycles);
  return d;
}

Design earthquake_design(const Earthquake& e, const std::filesystem::path& motions) {
  const auto dir = motions / "three-component";
  const Accelerogram h = model_scale_window(read_at2(dir / e.horizontal), e.start, e.end, 0.5, kTimeFactor, e.pga * kG);
  // The record's own vertical, scaled so that its peak equals the horizontal peak; the drawn
  // ratio multiplies it when the vertical motion is hidden in the data.
  const Accelerogram v = model_scale_window(read_at2(dir / e.vertical), e.start, e.end, 0.5, kTimeFactor, e.pga * kG);
  Design d;
  d.description = std::string(e.label) + ", time / sqrt(3), " + std::to_string(e.pga).substr(0, 4) + " g";
  d.horizontal = h;
  d.vertical_shape = v;
  d.duration = h.duration();
  return d;
}

std::vector<Design> programme(const std::filesystem::path& motions) {
  static const Earthquake elcentro{"El Centro 1940 180", "elcentro1940_RSN6_H1_180.AT2", "elcentro1940_RSN6_UP.AT2",
                                   0.0, 15.0, 0.70};
  static const Earthquake kobe{"Kobe 1995 KJMA 000", "kobe1995_RSN1106_KJMA_H1_000.AT2", "kobe1995_RSN1106_KJMA_UP.AT2",
                               4.0, 19.0, 0.65};
  static const Earthquake loma{"Loma Prieta 1989 Corralitos 000", "lomaprieta1989_RSN753_Corralitos_H1_000.AT2",
                               "lomaprieta1989_RSN753_Corralitos_UP.AT2", 0.0, 15.0, 0.70};
  return {sine_design(3.6, 6.0), sine_design(4.2, 6.0), earthquake_design(elcentro, motions),
          sine_design(5.0, 6.0), earthquake_design(kobe, motions),     earthquake_design(loma, motions)};
}

// The [cask] line that states the footprint rule.
std::string footprint_line(const std::string& footprint) {
  return footprint == "distributed" ? "footprint = \"distributed\"" : "half_width = \"" + footprint + "\"";
}

std::string specimen_text(const std::string& footprint) {
  return R"(title = "Shaking-table tests of the 1/3 model cask"
# Made by caskdem_independent_data (tests/independent): a model written apart from caskdem's.
# What the experimenter knows, with nominal values; the truth is in truth.json.

[cask]
shape = "cylinder"
diameter = "0.95 m"
height = "2.033 m"
density = "8.743 g/cm^3"
)" + footprint_line(footprint) + R"(
rounding = "0.5 cm"

[contact]
normal_stiffness = "2.38e3 bar/cm"
shear_stiffness = "2.21e3 bar/cm"

[friction]
law = "constant"
coefficient = 0.6

[damping]
ratio = 0.03
frequency = "135 Hz"

[integration]
safety_factor = 0.05

[diagnosis]
heldout = ["test2", "test5"]
starts = 6
evaluations = 50
seed = 1
)";
}

// One test of the truth's cask under `design`, recorded for `record_time` s at 200 Hz with the
// sensor noise of stream 100 + number (so a test's noise is its seed's and number's alone),
// written to DIRECTORY/NAME.csv; returns its summary and its truth.json entry.
std::pair<TestSummary, nlohmann::json> write_test(const std::filesystem::path& directory, int number,
                                                  const Design& design, double record_time, const Truth& truth,
                                                  std::uint64_t seed, const MeasuredSetOptions& options) {
  const CylinderModel model(truth.cask);
  const State rest = model.equilibrium();
  const double ratio = truth.vertical_ratio;
  TableInput input;
  input.horizontal = design.horizontal;
  if (ratio > 0.0 && design.vertical_shape)
    input.vertical = [&design, ratio](double t) { return ratio * design.vertical_shape(t); };

  const auto samples = static_cast<std::size_t>(std::floor(record_time / kSampleStep)) + 1;
  std::vector<double> times(samples);
  for (std::size_t k = 0; k < samples; ++k) times[k] = k * kSampleStep - truth.sensor_delay;
  const Response response = simulate(model, input, rest, times);

  const std::string name = "test" + std::to_string(number);
  RandomStream noise(seed, 100 + static_cast<std::uint64_t>(number));
  std::ofstream csv(directory / (name + ".csv"));
  csv << "# shaking-table test " << name << ": " << design.description << "; SI units, 200 Hz\n";
  csv << "t,table_acc,theta,slide,table_acc_v\n";
  TestSummary summary{name};
  char line[256];
  for (std::size_t k = 0; k < samples; ++k) {
    const double t = k * kSampleStep;
    const double av = input.vertical ? input.vertical(t) : 0.0;
    // Noise drawn in a fixed order per sample, so every channel's noise is the seed's alone.
    const double n0 = noise.normal(), n1 = noise.normal(), n2 = noise.normal(), n3 = noise.normal();
    std::snprintf(line, sizeof line, "%.3f,%.9g,%.9g,%.9g,%.9g\n", t, design.horizontal(t) + options.table_noise * n0,
                  response.rotation[k] + options.rotation_noise * n1, response.slide[k] + options.slide_noise * n2,
                  av + options.table_noise * n3);
    csv << line;
    summary.peak_rotation = std::max(summary.peak_rotation, std::abs(response.rotation[k]));
    summary.peak_slide = std::max(summary.peak_slide, std::abs(response.slide[k]));
  }
  summary.final_slide = response.slide.back();
  summary.tipped_over = response.tipped_over;
  summary.evaluations = response.steps;
  nlohmann::json entry = {{"name", name},
                          {"motion", design.description},
                          {"peak_rotation_rad", summary.peak_rotation},
                          {"peak_slide_m", summary.peak_slide},
                          {"final_slide_m", summary.final_slide},
                          {"tipped_over", summary.tipped_over}};
  return {summary, entry};
}

// The drive file a plan writes (caskdem plan-test: "# ..." lines, then "t,table_acc", then
// uniformly spaced samples in s and m/s^2). Printed times are rounded: each interval is the first
// one to within 1 % of it, and the step is the span over the samples.
Design drive_design(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot be read");
  Design d;
  Accelerogram drive;
  double first_step = 0.0, previous = 0.0;
  std::string line, description;
  int number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    const auto where = [&] { return file.string() + ": line " + std::to_string(number) + ": "; };
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (line.front() == '#') {
      if (description.empty()) description = line.substr(std::min<std::size_t>(2, line.size()));
      continue;
    }
    if (!header) {
      if (line != "t,table_acc") throw std::runtime_error(where() + "expected the header 't,table_acc'");
      header = true;
      continue;
    }
    double t = 0.0, a = 0.0;
    char rest = 0;
    if (std::sscanf(line.c_str(), "%lf,%lf%c", &t, &a, &rest) != 2 || !std::isfinite(t) || !std::isfinite(a))
      throw std::runtime_error(where() + "expected a time and a table acceleration, not '" + line + "'");
    const std::size_t k = drive.acceleration.size();
    if (k == 0 && t != 0.0) throw std::runtime_error(where() + "expected the drive to start at t = 0");
    if (k == 1) first_step = t;
    if (k >= 1 && !(first_step > 0.0 && std::abs(t - previous - first_step) <= 0.01 * first_step))
      throw std::runtime_error(where() + "expected samples evenly spaced in time");
    previous = t;
    drive.acceleration.push_back(a);
  }
  if (drive.acceleration.size() < 2) throw std::runtime_error(file.string() + ": expected at least two samples");
  drive.time_step = previous / double(drive.acceleration.size() - 1);
  d.description = description.empty() ? "table drive " + file.filename().string() : description;
  d.duration = drive.duration();
  d.horizontal = drive;  // the table does not move vertically: no vertical_shape
  return d;
}

}  // namespace

MeasuredSetResult write_independent_measured_set(const std::filesystem::path& directory, const std::string& effect,
                                                 std::uint64_t seed, const MeasuredSetOptions& options) {
  if (options.footprint != "distributed" && options.footprint != "gyration" && options.footprint != "radius")
    throw std::invalid_argument("footprint must be 'distributed', 'gyration' or 'radius', not '" + options.footprint + "'");
  MeasuredSetResult result;
  result.truth = draw_truth(effect, seed);
  const Truth& truth = result.truth;
  const std::vector<Design> designs = programme(options.motions.empty() ? INDEPENDENT_MOTIONS_DIR : options.motions);
  std::vector<int> chosen = options.tests;
  if (chosen.empty())
    for (int i = 1; i <= static_cast<int>(designs.size()); ++i) chosen.push_back(i);

  std::filesystem::create_directories(directory);
  // Tests an earlier --drive added to a set here would be read as tests of this one.
  if (std::ifstream earlier(directory / "truth.json"); earlier) {
    const nlohmann::json old = nlohmann::json::parse(earlier, nullptr, false);
    if (old.is_object() && old.contains("tests") && old["tests"].is_array())
      for (const auto& test : old["tests"])
        if (test.is_object() && test.contains("drive_file") && test.contains("name") && test["name"].is_string())
          std::filesystem::remove(directory / (test["name"].get<std::string>() + ".csv"));
  }
  std::ofstream(directory / "specimen.toml") << specimen_text(options.footprint);

  const CylinderModel model(truth.cask);
  const State rest = model.equilibrium();
  nlohmann::json tests_json = nlohmann::json::array();
  for (int number : chosen) {
    if (number < 1 || number > static_cast<int>(designs.size()))
      throw std::invalid_argument("no test " + std::to_string(number));
    const Design& design = designs[number - 1];
    auto [summary, entry] =
        write_test(directory, number, design, design.duration + options.free_time, truth, seed, options);
    result.tests.push_back(summary);
    tests_json.push_back(entry);
  }

  nlohmann::json j;
  j["generator"] = "independent";
  j["hidden"] = truth.effect == "none" ? std::vector<std::string>{} : std::vector<std::string>{truth.effect};
  j["effect"] = truth.effect;
  for (const auto& [key, value] : truth.effect_parameters) j["effect_parameters"][key] = value;
  const CaskParameters& c = truth.cask;
  j["true"] = {{"friction", truth.friction},
               {"normal_stiffness_N_m3", truth.stiffness},
               {"stiffness_scale", truth.stiffness_scale},
               {"standing_damping_ratio", truth.damping_ratio},
               {"hunt_crossley_k_h", c.k_h},
               {"hunt_crossley_exponent", c.exponent},
               {"hunt_crossley_c_h_s_m", c.c_h},
               {"friction_regularisation_m_s", c.regularisation},
               {"static_settlement_m", c.half_height + c.camber - rest[1]},
               {"mass_kg", c.mass()},
               {"slenderness_rad", c.slenderness()}};
  j["specimen_footprint"] = options.footprint;
  j["seed"] = seed;
  j["noise"] = {{"rotation_rad", options.rotation_noise}, {"slide_m", options.slide_noise}, {"table_m_s2", options.table_noise}};
  j["tests"] = tests_json;
  std::ofstream(directory / "truth.json") << j.dump(2) << "\n";
  return result;
}

TestSummary add_drive_test(const std::filesystem::path& directory, const std::string& effect, std::uint64_t seed,
                           const std::filesystem::path& drive_file, int number, const MeasuredSetOptions& options) {
  const auto truth_file = directory / "truth.json";
  std::ifstream truth_in(truth_file);
  if (!truth_in) throw std::runtime_error(truth_file.string() + ": cannot be read; write the set first");
  nlohmann::json j = nlohmann::json::parse(truth_in);
  if (j.value("effect", "") != effect || j.value("seed", std::uint64_t{0}) != seed)
    throw std::invalid_argument(truth_file.string() + ": the set was made with effect " + j.value("effect", "?") +
                                " and seed " + std::to_string(j.value("seed", std::uint64_t{0})) +
                                "; the added test must use the same");
  const std::string name = "test" + std::to_string(number);
  if (number < 1 || std::filesystem::exists(directory / (name + ".csv")))
    throw std::invalid_argument(directory.string() + ": " + name + " already exists or is not a test number");
  const Truth truth = draw_truth(effect, seed);
  const Design design = drive_design(drive_file);
  MeasuredSetOptions same = options;  // the set's own noise levels
  same.rotation_noise = j.at("noise").at("rotation_rad").get<double>();
  same.slide_noise = j.at("noise").at("slide_m").get<double>();
  same.table_noise = j.at("noise").at("table_m_s2").get<double>();
  // The recording spans the drive, whose end is already a rest.
  auto [summary, entry] = write_test(directory, number, design, design.duration, truth, seed, same);
  entry["drive_file"] = drive_file.string();
  j["tests"].push_back(entry);
  std::ofstream(truth_file) << j.dump(2) << "\n";
  return summary;
}

}  // namespace independent
