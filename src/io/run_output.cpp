#include "io/run_output.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "caskdem/build_info.h"
#include "core/units.h"
#include "io/hdf5_file.h"
#include "model/build.h"

namespace caskdem {

namespace {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

nlohmann::json summary_json(const RunReport& report) {
  const RunSummary& s = report.result.summary;
  nlohmann::json j;
  j["caskdem_version"] = build_info::version;
  if (report.source) j["case_file"] = report.source->file.string();
  j["max_abs_rotation_rad"] = s.max_abs_rotation;
  j["stability_angle_rad"] = s.stability_angle;
  j["max_rotation_ratio"] = s.max_rotation_ratio;
  j["max_abs_slide_m"] = s.max_abs_slide;
  j["residual_slide_m"] = s.residual_slide;
  j["max_uplift_m"] = s.max_uplift;
  j["status"] = status_name(s.status);
  j["tipped_over"] = s.tipped_over;
  if (s.tipped_over) {
    j["tip_over_time_s"] = s.tip_over_time;
    j["instability_time_s"] = s.instability_time;
  }
  j["impacts"] = s.impacts;
  j["end_time_s"] = s.end_time;
  j["time_step_s"] = s.time_step;
  j["steps"] = s.steps;
  j["wall_time_s"] = report.wall_seconds;
  return j;
}

}  // namespace

void print_summary(std::ostream& out, const RunReport& report) {
  const RunSummary& s = report.result.summary;
  const ModelFacts& f = report.facts;
  out << std::setprecision(4);
  out << "case            " << (report.source ? report.source->title : "") << "\n";
  out << "time step       " << s.time_step << " s (" << s.steps << " steps, " << report.wall_seconds << " s wall), "
      << slider_name_of(report.model.whole_step_terms) << " slider\n";
  out << "alpha           " << s.stability_angle << " rad (" << units::rad_to_deg(s.stability_angle) << " deg)\n";
  out << "contact         " << contact_law_text(report.model, f.normal_damper) << ", K_n " << f.total_normal_stiffness << " N/m, static penetration " << f.static_penetration
      << " m, beta " << f.damping_beta << " s\n";
  out << "max |theta|     " << s.max_abs_rotation << " rad = " << s.max_rotation_ratio << " alpha\n";
  out << "sliding         max " << s.max_abs_slide << " m, residual " << s.residual_slide << " m\n";
  out << "max uplift      " << s.max_uplift << " m\n";
  out << "impacts         " << s.impacts << "\n";
  out << "result          " << status_name(s.status);
  if (s.tipped_over) out << " at t = " << s.tip_over_time << " s (passed alpha at t = " << s.instability_time << " s)";
  out << "\n";
}

void write_summary_json(const std::filesystem::path& file, const RunReport& report) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error(file.string() + ": cannot write");
  out << summary_json(report).dump(2) << "\n";
}

std::string summary_json_text(const RunReport& report) { return summary_json(report).dump(2); }

std::vector<HistoryColumn> history_columns(const RunReport& report) {
  const TimeHistory& h = report.result.history;
  std::vector<HistoryColumn> columns = {{"time_s", "s", h.time},
                                        {"rotation_rad", "rad", h.rotation},
                                        {"angular_velocity_rad_s", "rad/s", h.angular_velocity},
                                        {"slide_m", "m", h.slide},
                                        {"uplift_m", "m", h.uplift},
                                        {"table_acceleration_m_s2", "m/s^2", h.table_acceleration},
                                        {"table_velocity_m_s", "m/s", h.table_velocity},
                                        {"table_displacement_m", "m", h.table_displacement},
                                        {"table_vertical_acceleration_m_s2", "m/s^2", h.table_vertical_acceleration}};
  for (std::size_t k = 0; k < h.normal_force.size(); ++k) {
    columns.push_back({"normal_force_" + std::to_string(k) + "_N", "N", h.normal_force[k]});
  }
  for (std::size_t k = 0; k < h.shear_force.size(); ++k) {
    columns.push_back({"shear_force_" + std::to_string(k) + "_N", "N", h.shear_force[k]});
  }
  return columns;
}

void write_columns_csv(const std::filesystem::path& file, const std::vector<HistoryColumn>& columns) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error(file.string() + ": cannot write");
  // No comment line: pandas and numpy read the header with their defaults. What the run was (the
  // version, the case, the summary) is in summary.json beside it; every column's unit is in its name.
  for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c].name;
  out << "\n" << std::setprecision(10);
  const std::size_t rows = columns.empty() ? 0 : columns.front().values.size();
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "," : "") << columns[c].values[i];
    out << '\n';
  }
}

void write_history_csv(const std::filesystem::path& file, const RunReport& report) {
  write_columns_csv(file, history_columns(report));
}

void write_run_attributes(hdf5::Group& root, const Case* source, double wall_seconds) {
  root.attribute("caskdem_version", std::string(build_info::version));
  if (source) {
    root.attribute("case_file", source->file.string());
    root.attribute("case_toml", read_text(source->file));
    root.attribute("title", source->title);
  }
  root.attribute("wall_time_s", wall_seconds);
}

void write_run_hdf5(const std::filesystem::path& file, const RunReport& report) {
  const RunSummary& s = report.result.summary;
  const TimeHistory& h = report.result.history;
  hdf5::Group root = hdf5::create_file(file);
  write_run_attributes(root, report.source, report.wall_seconds);

  hdf5::Group summary = root.group("summary");
  summary.attribute("max_abs_rotation_rad", s.max_abs_rotation);
  summary.attribute("stability_angle_rad", s.stability_angle);
  summary.attribute("max_rotation_ratio", s.max_rotation_ratio);
  summary.attribute("max_abs_slide_m", s.max_abs_slide);
  summary.attribute("residual_slide_m", s.residual_slide);
  summary.attribute("max_uplift_m", s.max_uplift);
  summary.attribute("status", status_name(s.status));
  summary.attribute("tipped_over", std::int64_t(s.tipped_over));
  summary.attribute("tip_over_time_s", s.tip_over_time);
  summary.attribute("instability_time_s", s.instability_time);
  summary.attribute("impacts", std::int64_t(s.impacts));
  summary.attribute("end_time_s", s.end_time);
  summary.attribute("time_step_s", s.time_step);
  summary.attribute("steps", std::int64_t(s.steps));

  hdf5::Group model = root.group("model");
  const Model& m = report.model;
  std::vector<double> corner_x(m.corner_x, m.corner_x + m.corner_count);
  std::vector<double> corner_y(m.corner_y, m.corner_y + m.corner_count);
  std::vector<double> kn(m.corner_normal_stiffness, m.corner_normal_stiffness + m.corner_count);
  std::vector<double> ks(m.corner_shear_stiffness, m.corner_shear_stiffness + m.corner_count);
  model.write("corner_x", corner_x, "m");
  model.write("corner_y", corner_y, "m");
  model.write("corner_normal_stiffness", kn, "N/m");
  model.write("corner_shear_stiffness", ks, "N/m");
  model.attribute("rounding_radius_m", m.rounding_radius);
  model.attribute("total_normal_stiffness_N_m", report.facts.total_normal_stiffness);
  model.attribute("static_penetration_m", report.facts.static_penetration);
  model.attribute("damping_beta_s", report.facts.damping_beta);
  model.attribute("natural_frequency_rad_s", report.facts.natural_frequency);
  model.attribute("tip_over_angle_rad", m.tip_over_angle);
  model.attribute("slider", slider_name_of(m.whole_step_terms));
  model.attribute("normal_law", normal_law_name(m.normal_law));
  if (m.normal_law == NormalLaw::hunt_crossley) model.attribute("hertz_overlap_m", m.hertz_overlap);
  model.attribute("impact_damping_s_m", report.facts.normal_damper);
  if (report.source) {
    model.attribute("mass_kg", report.source->parameters.mass);
    model.attribute("inertia_kg_m2", report.source->parameters.inertia);
    model.attribute("centre_of_mass_height_m", report.source->parameters.centre_of_mass.y);
  }

  if (!h.time.empty()) {
    hdf5::Group history = root.group("history");
    history.write("time", h.time, "s");
    history.write("rotation", h.rotation, "rad");
    history.write("angular_velocity", h.angular_velocity, "rad/s");
    history.write("slide", h.slide, "m");
    history.write("uplift", h.uplift, "m");
    history.write("centre_x", h.centre_x, "m");
    history.write("centre_y", h.centre_y, "m");
    history.write("table_acceleration", h.table_acceleration, "m/s^2");
    history.write("table_velocity", h.table_velocity, "m/s");
    history.write("table_displacement", h.table_displacement, "m");
    history.write("table_vertical_acceleration", h.table_vertical_acceleration, "m/s^2");
    const std::size_t corners = h.normal_force.size();
    std::vector<double> normal, shear;
    for (std::size_t k = 0; k < corners; ++k) normal.insert(normal.end(), h.normal_force[k].begin(), h.normal_force[k].end());
    for (std::size_t k = 0; k < corners; ++k) shear.insert(shear.end(), h.shear_force[k].begin(), h.shear_force[k].end());
    history.write_matrix("normal_force", normal, corners, h.time.size(), "N");
    history.write_matrix("shear_force", shear, corners, h.time.size(), "N");
  }
}

// The interpreter is started without a shell, its arguments passed as a vector: no path (a
// quote, a space, a `$(...)`) can break the command or run one of its own.
void run_plot_script(const std::string& script, const std::vector<std::string>& arguments) {
  const std::filesystem::path path = std::filesystem::path(build_info::source_dir) / "src" / "plots" / script;
  std::vector<std::string> words = {build_info::python, path.string()};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);

  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("cannot start " + std::string(build_info::python) + ": no pipe");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[1]);
  pid_t child = 0;
  const int spawned = posix_spawn(&child, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  std::string output;
  char buffer[512];
  for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) != 0;) {
    if (n > 0) output.append(buffer, static_cast<std::size_t>(n));
    else if (errno != EINTR) break;
  }
  close(fds[0]);
  if (spawned != 0) throw std::runtime_error("cannot start " + std::string(build_info::python) + ": " + std::strerror(spawned));
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error("plotting with " + script + " failed:\n" + output);
  }
}

}  // namespace caskdem
