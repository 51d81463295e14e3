#include "io/run_output3d.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "caskdem/build_info.h"
#include "core/units.h"
#include "io/hdf5_file.h"
#include "io/run_output.h"
#include "model/build.h"

namespace caskdem {

namespace {

// One list of the summary's figures, for the JSON and the HDF5 attributes alike.
template <class Put>
void each_summary_figure(const RunReport3D& report, Put&& put) {
  const RunSummary3D& s = report.result.summary;
  put("max_tilt_rad", s.max_tilt);
  put("stability_angle_rad", s.stability_angle);
  put("max_tilt_ratio", s.max_tilt_ratio);
  put("max_slide_m", s.max_slide);
  put("residual_slide_m", s.residual_slide);
  put("max_slip_m", s.max_slip);
  put("residual_slip_m", s.residual_slip);
  put("max_uplift_m", s.max_uplift);
  put("spin_rad", s.spin);
  put("rim_revolutions", s.rim_revolutions);
  put("instability_time_s", s.instability_time);
  put("end_time_s", s.end_time);
  put("time_step_s", s.time_step);
  put("incidence_rad", report.motions.incidence);
  put("scale_factor", report.motions.scale_factor);
  if (report.motions.pair) {
    const motion::PairIntensity& p = *report.motions.pair;
    put("pga_rotd50_m_s2", p.pga_rotd50);
    put("pga_rotd100_m_s2", p.pga_rotd100);
    put("pga_geometric_mean_m_s2", p.pga_geometric_mean);
    put("pgv_rotd50_m_s", p.pgv_rotd50);
    put("pgv_rotd100_m_s", p.pgv_rotd100);
    put("pgv_geometric_mean_m_s", p.pgv_geometric_mean);
  }
}

}  // namespace

void print_summary3d(std::ostream& out, const RunReport3D& report) {
  const RunSummary3D& s = report.result.summary;
  out << std::setprecision(4);
  out << "case            " << (report.source ? report.source->title : "") << " (3D)\n";
  out << "time step       " << s.time_step << " s (" << report.wall_seconds << " s wall), "
      << slider_name_of(report.model.model.whole_step_terms) << " slider, "
      << contact_law_text(report.model.model, lane_parameters3d(report.model, report.parameters).impact_damping)
      << "\n";
  out << "alpha           " << s.stability_angle << " rad (" << units::rad_to_deg(s.stability_angle) << " deg)\n";
  out << "motion          incidence " << units::rad_to_deg(report.motions.incidence) << " deg, scale "
      << report.motions.scale_factor;
  if (report.motions.pair) {
    out << ", pair PGA RotD50 " << report.motions.pair->pga_rotd50 << " m/s^2, RotD100 " << report.motions.pair->pga_rotd100
        << " m/s^2";
  }
  out << "\n";
  if (!report.motions.time_base.empty()) out << "time base       " << report.motions.time_base << "\n";
  out << "max tilt        " << s.max_tilt << " rad = " << s.max_tilt_ratio << " alpha\n";
  out << "base walk       max " << s.max_slide << " m, residual " << s.residual_slide
      << " m (the base centre: sliding and rolling on the rim)\n";
  out << "slip            max " << s.max_slip << " m, residual " << s.residual_slip
      << " m (sliding over the floor where it bears, rolling excluded)\n";
  out << "max uplift      " << s.max_uplift << " m\n";
  out << "spin            " << s.spin << " rad about the axis; " << s.rim_revolutions
      << " revolutions of the contact around the rim (rolling)\n";
  out << "result          " << status_name(s.status);
  if (s.status == LaneStatus::tipped_over) {
    out << " at t = " << s.end_time << " s (passed alpha at t = " << s.instability_time << " s)";
  }
  out << "\n";
  if (s.rest_criterion && s.status == LaneStatus::running) {
    out << "end             ";
    if (s.came_to_rest) {
      out << "at rest at t = " << s.end_time << " s (kinetic energy below " << kRestEnergy << " m g H for " << kRestHold
          << " s after the motion)\n";
    } else {
      out << "still moving at t = " << s.end_time << " s, the cap ([integration] rest_cap; kinetic energy "
          << s.kinetic_energy_at_end << " J): the residual slide and spin are not settled\n";
    }
  }
}

std::string summary_json_text3d(const RunReport3D& report) {
  nlohmann::json j;
  j["caskdem_version"] = build_info::version;
  if (report.source) j["case_file"] = report.source->file.string();
  j["dimensions"] = 3;
  each_summary_figure(report, [&](const char* key, double value) { j[key] = value; });
  j["status"] = status_name(report.result.summary.status);
  j["tipped_over"] = report.result.summary.status == LaneStatus::tipped_over;
  j["time_base"] = report.motions.time_base;
  if (report.result.summary.rest_criterion) j["came_to_rest"] = report.result.summary.came_to_rest;
  j["wall_time_s"] = report.wall_seconds;
  return j.dump(2);
}

void write_summary_json3d(const std::filesystem::path& file, const RunReport3D& report) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error(file.string() + ": cannot write");
  out << summary_json_text3d(report) << "\n";
}

std::vector<HistoryColumn> history_columns3d(const RunReport3D& report) {
  // x and z are horizontal, y is up (docs/output.md).
  const TimeHistory3D& h = report.result.history;
  std::vector<double> slide(h.time.size()), slip(h.time.size());
  for (std::size_t i = 0; i < h.time.size(); ++i) {
    slide[i] = std::hypot(h.slide_x[i], h.slide_z[i]);
    slip[i] = std::hypot(h.slip_x[i], h.slip_z[i]);
  }
  return {{"time_s", "s", h.time},
          {"tilt_rad", "rad", h.tilt},
          {"tilt_azimuth_rad", "rad", h.tilt_azimuth},
          {"spin_rad", "rad", h.spin},
          {"rim_contact_azimuth_rad", "rad", h.rim_azimuth},
          {"slide_x_m", "m", h.slide_x},
          {"slide_z_m", "m", h.slide_z},
          {"slide_m", "m", slide},
          {"slip_x_m", "m", h.slip_x},
          {"slip_z_m", "m", h.slip_z},
          {"slip_m", "m", slip},
          {"uplift_m", "m", h.uplift},
          {"table_x_m_s2", "m/s^2", h.table_x},
          {"table_z_m_s2", "m/s^2", h.table_z},
          {"table_vertical_m_s2", "m/s^2", h.table_vertical}};
}

void write_history_csv3d(const std::filesystem::path& file, const RunReport3D& report) {
  write_columns_csv(file, history_columns3d(report));
}

void write_run_hdf5_3d(const std::filesystem::path& file, const RunReport3D& report) {
  const RunSummary3D& s = report.result.summary;
  const TimeHistory3D& h = report.result.history;
  hdf5::Group root = hdf5::create_file(file);
  write_run_attributes(root, report.source, report.wall_seconds);
  root.attribute("dimensions", std::int64_t(3));

  hdf5::Group summary = root.group("summary");
  each_summary_figure(report, [&](const char* key, double value) { summary.attribute(key, value); });
  summary.attribute("status", status_name(s.status));
  summary.attribute("tipped_over", std::int64_t(s.status == LaneStatus::tipped_over));
  summary.attribute("time_base", report.motions.time_base);

  hdf5::Group model = root.group("model");
  model.attribute("radius_m", report.cask.radius);
  model.attribute("height_m", report.cask.height);
  model.attribute("rounding_radius_m", report.cask.rounding);
  model.attribute("mass_kg", report.parameters.mass);
  model.attribute("inertia_kg_m2", report.parameters.inertia);
  model.attribute("axial_inertia_kg_m2", report.parameters.axial_inertia);
  model.attribute("centre_of_mass_height_m", report.parameters.centre_of_mass.y);
  model.attribute("standing_normal_stiffness_N_m", standing_stiffness(report.model.contacts));
  model.attribute("tip_over_angle_rad", report.model.model.tip_over_angle);
  model.attribute("slider", slider_name_of(report.model.model.whole_step_terms));
  model.attribute("normal_law", normal_law_name(report.model.model.normal_law));
  if (report.model.model.normal_law == NormalLaw::hunt_crossley) {
    model.attribute("hertz_overlap_m", report.model.model.hertz_overlap);
  }
  model.attribute("impact_damping_s_m", lane_parameters3d(report.model, report.parameters).impact_damping);

  if (!h.time.empty()) {
    hdf5::Group history = root.group("history");
    history.write("time", h.time, "s");
    history.write("tilt", h.tilt, "rad");
    history.write("tilt_azimuth", h.tilt_azimuth, "rad");
    history.write("spin", h.spin, "rad");
    history.write("slip_x", h.slip_x, "m");
    history.write("slip_z", h.slip_z, "m");
    history.write("rim_contact_azimuth", h.rim_azimuth, "rad");
    history.write("slide_x", h.slide_x, "m");
    history.write("slide_z", h.slide_z, "m");
    history.write("uplift", h.uplift, "m");
    history.write("centre_x", h.centre_x, "m");
    history.write("centre_y", h.centre_y, "m");
    history.write("centre_z", h.centre_z, "m");
    history.write("table_x", h.table_x, "m/s^2");
    history.write("table_z", h.table_z, "m/s^2");
    history.write("table_vertical", h.table_vertical, "m/s^2");
  }
}

}  // namespace caskdem
