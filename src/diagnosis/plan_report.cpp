#include "diagnosis/plan_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "caskdem/build_info.h"
#include "core/error.h"
#include "core/text.h"
#include "diagnosis/measured_test.h"
#include "io/hdf5_file.h"
#include "io/run_output.h"
#include "motion/record.h"

namespace caskdem::diagnosis {

namespace {

std::string number(double v, int precision = 3) {
  std::ostringstream out;
  out << std::setprecision(precision) << v;
  return out.str();
}

// A limit that is not limited reads as null in JSON.
nlohmann::json limit(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// What a candidate predicts for a test, in the units the table operator reads.
struct Predicted {
  double peak_rotation = 0.0;  // rad
  double max_sliding = 0.0;    // m
};

Predicted predicted_of(const SimulatedHistory& h) {
  Predicted p;
  for (double r : h.rotation) p.peak_rotation = std::max(p.peak_rotation, std::abs(r));
  for (double s : h.slide) p.max_sliding = std::max(p.max_sliding, std::abs(s));
  return p;
}

std::size_t shown(const TestPlan& plan) { return std::min<std::size_t>(kProposedTests, plan.tests.size()); }

std::string drive_file_name(std::size_t rank) { return "drive-" + std::to_string(rank + 1) + ".csv"; }

// The table drive of a proposed test in the measured tests' CSV layout (what the table operator
// runs; the laboratory's recording of it is the new test's table channel).
void write_drive(const std::filesystem::path& file, std::size_t rank, const ProposedTest& p) {
  std::ofstream out(file);
  out << "# proposed test " << rank + 1 << ": " << p.description << "\n"
      << "# the table drive"
      << (p.kind == "record" ? " (the measured table channel scaled, its sensor noise included)" : ", noise-free")
      << "; model scale, SI units (s, m/s^2), every " << p.input.time_step << " s; the table does not move vertically\n"
      << "t,table_acc\n";
  char line[64];
  for (std::size_t k = 0; k < p.drive.size(); ++k) {
    std::snprintf(line, sizeof line, "%.*f,%.9g\n", time_decimals(p.input.time_step), double(k) * p.input.time_step,
                  p.drive[k]);
    out << line;
  }
}

}  // namespace

std::string plan_markdown(const TestPlan& plan) {
  std::ostringstream md;
  md << "## The test that would settle it\n\n";
  if (plan.candidates.size() < 2) {
    md << "Only the baseline is left standing (no mechanism has a profile likelihood ratio of at least 3.84 against "
          "it): there is nothing for a further test to tell apart.\n";
    return md.str();
  }
  md << "Candidates, at their fitted values (model scale, SI):\n\n";
  for (std::size_t c = 0; c < plan.candidates.size(); ++c) {
    md << "- " << plan.candidates[c].name << ":";
    for (std::size_t i = 0; i < plan.parameters[c].size() && i < plan.candidates[c].point.size(); ++i) {
      const Parameter& p = plan.parameters[c][i];
      md << (i ? ", " : " ") << p.name << " " << number(plan.candidates[c].point[i], 4) << (p.units.empty() ? "" : " ")
         << p.units;
    }
    md << "\n";
  }
  md << "\nTable limits: " << plan.limits_source << ".\n\n"
     << plan.tests.size() << " feasible tests were simulated with every candidate. A test's separation is the "
     << "smallest, over pairs of candidates, of the loss one would take were the other the truth, judged as the "
     << "diagnosis judges a measured test (sensor noise at this set's levels, the test's predictability, each fit's "
     << "standard errors): an expected log-likelihood ratio. Above 10.8 one such test decides between the closest "
     << "pair at the 0.001 level; below 1 it cannot tell them apart.\n\n";
  if (shown(plan) > 0) {
    const std::size_t n = shown(plan);
    md << (n == 1 ? "The table drive of the best test" : "The table drives of the best " + std::to_string(n))
       << " (model scale, SI; a sine's noise-free, a record's the measured channel scaled) "
       << (n == 1 ? "is in drive-1.csv" : "are in drive-1.csv to " + drive_file_name(n - 1)) << ".\n\n";
  }
  md << "| rank | test | separation | closest pair |";
  for (const PlanCandidate& c : plan.candidates) md << " " << c.name << ": peak rotation (rad), max sliding (mm) |";
  md << "\n|---|---|---|---|";
  for (std::size_t c = 0; c < plan.candidates.size(); ++c) md << "---|";
  md << "\n";
  for (std::size_t t = 0; t < shown(plan); ++t) {
    const ProposedTest& p = plan.tests[t];
    md << "| " << t + 1 << " | " << p.description << " | " << number(p.separation, 3) << " | " << p.closest_pair
       << " |";
    for (const SimulatedHistory& h : p.predicted) {
      const Predicted q = predicted_of(h);
      md << " " << number(q.peak_rotation, 3) << ", " << number(1e3 * q.max_sliding, 3) << " |";
    }
    md << "\n";
  }
  if (!plan.tests.empty() && plan.tests.front().separation < 1.0) {
    md << "\nNo feasible test separates the candidates beyond the noise: within these limits the table cannot tell "
          "them apart; a wider table, or another kind of measurement, would be needed.\n";
  }
  md << "\n![predicted histories of the proposed tests](plan.png)\n";
  return md.str();
}

void write_plan(const std::filesystem::path& directory, const TestPlan& plan, bool plots) {
  std::filesystem::create_directories(directory);
  nlohmann::json j;
  j["caskdem_version"] = build_info::version;
  j["table_limits"] = {{"peak_acceleration_m_s2", limit(plan.limits.peak_acceleration)},
                       {"peak_velocity_m_s", limit(plan.limits.peak_velocity)},
                       {"stroke_m", limit(plan.limits.stroke)},
                       {"frequencies_hz", {plan.limits.min_frequency, plan.limits.max_frequency}},
                       {"source", plan.limits_source}};
  j["candidates"] = nlohmann::json::array();
  for (const PlanCandidate& c : plan.candidates) {
    nlohmann::json names = nlohmann::json::array();
    for (Mechanism m : c.mechanisms) names.push_back(mechanism_name(m));
    nlohmann::json values = nlohmann::json::object();
    const std::size_t index = static_cast<std::size_t>(&c - plan.candidates.data());
    for (std::size_t i = 0; i < plan.parameters[index].size() && i < c.point.size(); ++i) {
      values[plan.parameters[index][i].name] = {
          {"value", c.point[i]},
          {"standard_error", i < c.standard_error.size() ? nlohmann::json(c.standard_error[i]) : nlohmann::json(nullptr)},
          {"units", plan.parameters[index][i].units}};
    }
    j["candidates"].push_back({{"name", c.name}, {"mechanisms", names}, {"parameters", values}});
  }
  j["separation"] =
      "min over candidate pairs of min(J_ab, J_ba): the loss b takes beyond a's own were a the truth "
      "(an expected log-likelihood ratio; 10.83 decides at the 0.001 level)";
  j["tests"] = nlohmann::json::array();
  for (const ProposedTest& p : plan.tests) {
    nlohmann::json t = {{"kind", p.kind},
                        {"description", p.description},
                        {"peak_acceleration_m_s2", p.peak_acceleration},
                        {"separation", p.separation},
                        {"closest_pair", p.closest_pair},
                        {"pair_loss", p.pair_loss}};
    if (p.kind == "sine") t["frequency_hz"] = p.frequency;
    if (p.kind == "record") t["scale"] = p.scale;
    const std::size_t rank = j["tests"].size();
    if (rank < shown(plan)) t["drive_file"] = drive_file_name(rank);
    t["predicted"] = nlohmann::json::array();
    for (const SimulatedHistory& h : p.predicted) {
      const Predicted q = predicted_of(h);
      t["predicted"].push_back({{"peak_rotation_rad", q.peak_rotation}, {"max_sliding_m", q.max_sliding}});
    }
    j["tests"].push_back(t);
  }
  j["wall_time_s"] = plan.wall_seconds;
  std::ofstream(directory / "plan.json") << j.dump(2) << "\n";
  std::ofstream(directory / "plan.md") << "# Proposed tests\n\n" << plan_markdown(plan);
  for (std::size_t t = 0; t < kProposedTests; ++t) {  // an earlier plan's drives beyond this one's go
    if (t < shown(plan)) {
      write_drive(directory / drive_file_name(t), t, plan.tests[t]);
    } else {
      std::filesystem::remove(directory / drive_file_name(t));
    }
  }

  {  // closed before the plot reads it
    hdf5::Group root = hdf5::create_file(directory / "plan-histories.h5");
    std::string names;
    for (const PlanCandidate& c : plan.candidates) names += (names.empty() ? "" : ",") + c.name;
    root.attribute("candidates", names);
    for (std::size_t t = 0; t < shown(plan); ++t) {
      const ProposedTest& p = plan.tests[t];
      hdf5::Group g = root.group("rank" + std::to_string(t + 1));
      g.attribute("description", p.description);
      g.attribute("separation", p.separation);
      g.write("time", p.input.time, "s");
      g.write("table_acceleration", p.input.table_acceleration, "m/s^2");
      for (std::size_t c = 0; c < plan.candidates.size(); ++c) {
        g.write(plan.candidates[c].name + "_rotation", p.predicted[c].rotation, "rad");
        g.write(plan.candidates[c].name + "_slide", p.predicted[c].slide, "m");
      }
    }
  }
  if (plots && shown(plan) > 0 && plan.candidates.size() > 1) {
    run_plot_script("plot_plan.py", {(directory / "plan-histories.h5").string(), (directory / "plan.png").string()});
  }
}

int time_decimals(double time_step) {
  return std::abs(1e3 * time_step - std::round(1e3 * time_step)) < 1e-9 ? 3 : 9;
}

TableDrive read_drive(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) fail_at(file, 0, "cannot be read; expected a table drive (drive-1.csv of a plan)");
  TableDrive drive;
  double first_step = 0.0, previous = 0.0;
  long last_line = 0;
  std::string line;
  long number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (line.front() == '#') {
      if (drive.description.empty()) drive.description = line.substr(std::min<std::size_t>(2, line.size()));
      continue;
    }
    if (!header) {
      if (line != "t,table_acc") fail_at(file, number, "expected the header 't,table_acc', not '" + line + "'");
      header = true;
      continue;
    }
    double t = 0.0, a = 0.0;
    char rest = 0;
    if (std::sscanf(line.c_str(), "%lf,%lf%c", &t, &a, &rest) != 2 || !std::isfinite(t) || !std::isfinite(a))
      fail_at(file, number, "expected a time in s and a table acceleration in m/s^2, not '" + line + "'");
    const std::size_t k = drive.acceleration.size();
    if (k == 0 && t != 0.0) fail_at(file, number, "expected the drive to start at t = 0");
    if (k == 1) first_step = t;
    // Printed times are rounded: each interval is the first one to within 1 % of it.
    if (k >= 1 && !(first_step > 0.0 && std::abs(t - previous - first_step) <= 0.01 * first_step))
      fail_at(file, number, "expected samples evenly spaced in time");
    previous = t;
    last_line = number;
    drive.acceleration.push_back(a);
  }
  if (drive.acceleration.size() < 2) fail_at(file, 0, "expected at least two samples after the header");
  // The step from the span, which rounding hardly touches; a drive is as fine and as long as a
  // measured test may be.
  drive.time_step = previous / double(drive.acceleration.size() - 1);
  if (!(drive.time_step >= kSmallestSamplingStep) || drive.time_step > motion::kLargestRecordTimeStep)
    fail_at(file, last_line, "the drive's step is " + number_text(drive.time_step) + " s; expected " +
                                    number_text(kSmallestSamplingStep) + " to " + number_text(motion::kLargestRecordTimeStep) +
                                    " s (is t in seconds?)");
  if (previous > motion::kLongestRecord)
    fail_at(file, last_line, "the drive lasts " + number_text(previous) + " s; expected at most " +
                                    number_text(motion::kLongestRecord) + " s");
  if (drive.description.empty()) drive.description = "table drive " + file.filename().string();
  return drive;
}

}  // namespace caskdem::diagnosis
