#include "ensemble/results.h"

#include <cmath>

#include "caskdem/build_info.h"
#include "core/error.h"
#include "ensemble/analysis.h"
#include "ensemble/limit_state_file.h"
#include "io/hdf5_file.h"
#include "model/build.h"

namespace caskdem {

namespace {

// The per-realisation datasets, named once for writing and reading.
template <class F>
void for_each_double(EnsembleResults& r, F&& f) {
  f("level", r.level, r.level_unit.c_str());
  f("scale_factor", r.scale_factor, "1");
  f("friction_static", r.friction_static, "1");
  f("friction_kinetic", r.friction_kinetic, "1");
  f("friction_decay_speed", r.friction_decay_speed, "m/s");
  f("restitution", r.restitution, "1");
  f("damping_ratio", r.damping_ratio, "1");
  f("mass", r.mass, "kg");
  f("centre_height", r.centre_height, "m");
  f("max_abs_rotation", r.max_abs_rotation, "rad");
  f("max_rotation_ratio", r.max_rotation_ratio, "1");
  f("max_abs_slide", r.max_abs_slide, "m");
  f("residual_slide", r.residual_slide, "m");
  f("max_uplift", r.max_uplift, "m");
  f("end_time", r.end_time, "s");
  f("tip_over_time", r.tip_over_time, "s");
  f("instability_time", r.instability_time, "s");
  if (r.three_d) {
    f("incidence", r.incidence, "rad");
    f("spin", r.spin, "rad");
    f("max_slip", r.max_slip, "m");
    f("residual_slip", r.residual_slip, "m");
  }
}

template <class F>
void for_each_integer(EnsembleResults& r, F&& f) {
  f("stripe", r.stripe);
  f("motion", r.motion);
  f("status", r.status);
  f("impacts", r.impacts);
}

constexpr const char* kResultFile = "a result file of caskdem ensemble";

// The realisations of an open result file (whose seal was checked), each of full length.
void read_realisations(const std::filesystem::path& file, const hdf5::Group& root, EnsembleResults& results) {
  results.size = root.integer_attribute("realisations");
  hdf5::Group realisations = root.open_group("realisations");
  results.completed = realisations.read_bytes("completed");
  for_each_double(results, [&](const char* name, std::vector<double>& v, const char*) { v = realisations.read_doubles(name); });
  for_each_integer(results, [&](const char* name, std::vector<std::int64_t>& v) { v = realisations.read_integers(name); });
  bool sized = static_cast<std::int64_t>(results.completed.size()) == results.size;
  for_each_double(results, [&](const char*, std::vector<double>& v, const char*) {
    sized = sized && static_cast<std::int64_t>(v.size()) == results.size;
  });
  for_each_integer(results, [&](const char*, std::vector<std::int64_t>& v) {
    sized = sized && static_cast<std::int64_t>(v.size()) == results.size;
  });
  if (!sized) throw InputError(located(file, 0, "its datasets are not all of the stated number of realisations"));
}

}  // namespace

EnsembleResults::EnsembleResults(const EnsemblePlan& plan)
    : size(plan.size()), three_d(plan.three_d()), level_unit(intensity_si_unit(plan.spec().measure)) {
  const auto n = static_cast<std::size_t>(size);
  completed.assign(n, 0);
  for_each_double(*this, [n](const char*, std::vector<double>& v, const char*) { v.assign(n, 0.0); });
  for_each_integer(*this, [n](const char*, std::vector<std::int64_t>& v) { v.assign(n, 0); });
  for (std::int64_t i = 0; i < size; ++i) {
    const RealisationInput in = plan.realisation(i);
    stripe[i] = in.stripe;
    motion[i] = in.motion;
    level[i] = in.level;
    scale_factor[i] = in.scale_factor;
    friction_static[i] = in.parameters.friction_static;
    friction_kinetic[i] = in.parameters.friction_kinetic;
    friction_decay_speed[i] = in.parameters.friction_decay_speed;
    restitution[i] = in.restitution;
    damping_ratio[i] = in.parameters.damping_ratio;
    mass[i] = in.parameters.mass;
    centre_height[i] = in.parameters.centre_of_mass.y;
    if (three_d) incidence[i] = in.incidence;
    tip_over_time[i] = -1.0;
    instability_time[i] = -1.0;
  }
}

void EnsembleResults::record(std::int64_t i, const RealisationOutcome& o, double stability_angle) {
  completed[i] = 1;
  status[i] = static_cast<std::int64_t>(o.status);
  impacts[i] = static_cast<std::int64_t>(o.impacts);
  max_abs_rotation[i] = o.max_abs_rotation;
  max_rotation_ratio[i] = o.max_abs_rotation / stability_angle;
  max_abs_slide[i] = o.max_abs_slide;
  residual_slide[i] = o.residual_slide;
  max_uplift[i] = o.max_uplift;
  end_time[i] = o.end_time;
  tip_over_time[i] = o.status == LaneStatus::tipped_over ? o.end_time : -1.0;
  instability_time[i] = o.instability_time;
  if (three_d) {
    spin[i] = o.spin;
    max_slip[i] = o.max_slip;
    residual_slip[i] = o.residual_slip;
  }
}

std::vector<EnsembleResults::Column> EnsembleResults::columns() const {
  std::vector<Column> out;
  auto& self = const_cast<EnsembleResults&>(*this);  // the visitors take mutable columns; none is changed
  for_each_integer(self, [&](const char* name, std::vector<std::int64_t>& v) {
    out.push_back({name, "1", nullptr, &v});  // indices, the status code and counts
  });
  for_each_double(self, [&](const char* name, std::vector<double>& v, const char* unit) {
    out.push_back({name, unit, &v, nullptr});
  });
  return out;
}

std::int64_t EnsembleResults::completed_count() const {
  std::int64_t count = 0;
  for (std::uint8_t c : completed) count += c;
  return count;
}

std::vector<std::int64_t> EnsembleResults::pending() const {
  std::vector<std::int64_t> indices;
  for (std::int64_t i = 0; i < size; ++i) {
    if (!completed[i]) indices.push_back(i);
  }
  return indices;
}

namespace {

// The result file's image, built in memory.
std::vector<char> result_image(const std::filesystem::path& file, const EnsemblePlan& plan, const EnsembleResults& results,
                               const RunInformation& run, const std::vector<LimitStateSummary>* limit_states) {
  const EnsembleSpec& spec = plan.spec();
  {
    hdf5::Group root = hdf5::create_in_memory(file.string());
    root.attribute("caskdem_version", std::string(build_info::version));
    root.attribute("ensemble_file", spec.file.string());
    root.attribute("ensemble_toml", spec.toml_text);
    root.attribute("title", spec.title);
    root.attribute("wall_time_s", run.wall_seconds);
    root.attribute("device", run.device);
    root.attribute("instruction_set", run.instruction_set);
    root.attribute("threads", std::int64_t(run.threads));
    root.attribute("realisations", results.size);
    root.attribute("completed", results.completed_count());
    std::int64_t non_finite = 0;
    for (std::int64_t i = 0; i < results.size; ++i) {
      non_finite += results.completed[i] && results.status[i] == std::int64_t(LaneStatus::non_finite);
    }
    // Realisations that went non-finite count in no stripe; their number is kept here.
    root.attribute("non_finite", non_finite);
    root.attribute("dimensions", std::int64_t(plan.three_d() ? 3 : 2));
    root.attribute("time_step_s", plan.model().time_step);
    root.attribute("slider", slider_name_of(plan.model().whole_step_terms));
    root.attribute("normal_law", normal_law_name(plan.model().normal_law));
    if (plan.model().normal_law == NormalLaw::hunt_crossley) root.attribute("hertz_overlap_m", plan.model().hertz_overlap);
    root.attribute("impact_damping_s_m", spec.base.parameters.impact_damping);
    root.attribute("stability_angle_rad", plan.stability_angle());
    root.attribute("frequency_parameter_rad_s", plan.frequency_parameter());
    root.attribute("intensity_measure", intensity_name(spec.measure));
    root.attribute("intensity_unit", intensity_si_unit(spec.measure));
    // 3: the stripes' intensities are a 1/3 model's, its motions prototype motions compressed in
    // time (their similarity_scale); 1: a full-size cask; 0: motions on models of several scales.
    root.attribute("model_scale", plan.model_scale());
    if (plan.three_d()) {
      root.attribute("pair_measure", std::string(spec.pair_measure == MotionSpec::PairMeasure::rotd100          ? "rotd100"
                                                 : spec.pair_measure == MotionSpec::PairMeasure::geometric_mean ? "geometric_mean"
                                                                                                                : "rotd50"));
    }
    if (spec.measure == IntensityMeasure::sa) {
      root.attribute("intensity_period_s", spec.spectral_period);
      root.attribute("intensity_damping_ratio", spec.spectral_damping_ratio);
    }
    root.attribute("seed", static_cast<std::int64_t>(spec.seed));
    root.attribute("epistemic_points", static_cast<std::int64_t>(spec.outer_count()));
    std::string epistemic;
    for (const std::string& name : spec.epistemic) epistemic += (epistemic.empty() ? "" : ",") + name;
    root.attribute("epistemic_parameters", epistemic);
    root.attribute("sampling", std::string(spec.sampling == SamplingMethod::latin_hypercube ? "latin_hypercube" : "monte_carlo"));

    hdf5::Group realisations = root.group("realisations");
    EnsembleResults& r = const_cast<EnsembleResults&>(results);  // the visitors are shared with reading
    realisations.write("completed", r.completed, "1");
    for_each_double(r, [&](const char* name, std::vector<double>& v, const char* units) { realisations.write(name, v, units); });
    // Indices, the status code and counts: dimensionless.
    for_each_integer(r, [&](const char* name, std::vector<std::int64_t>& v) { realisations.write(name, v, "1"); });

    hdf5::Group motions = root.group("motions");
    std::vector<double> pga, pgv, duration;
    for (int m = 0; m < plan.motion_count(); ++m) {
      pga.push_back(plan.intensity(m).pga);
      pgv.push_back(plan.intensity(m).pgv);
      duration.push_back(plan.intensity(m).duration);
    }
    motions.write_strings("name", spec.motion_names);
    motions.write("pga", pga, "m/s^2");
    motions.write("pgv", pgv, "m/s");
    motions.write("duration", duration, "s");
    if (spec.measure == IntensityMeasure::sa) {
      std::vector<double> sa;
      for (int m = 0; m < plan.motion_count(); ++m) sa.push_back(plan.intensity(m).sa);
      motions.write("sa", sa, "m/s^2");
    }

    hdf5::Group stripes = root.group("stripes");
    stripes.write("level", spec.levels, intensity_si_unit(spec.measure));
    stripes.attribute("measure", intensity_name(spec.measure));

    if (plan.restitution_uncertain()) {
      hdf5::Group calibration = root.group("calibration");
      calibration.write("damping_ratio", plan.calibration().damping_ratio, "1");
      calibration.write("restitution", plan.calibration().restitution, "1");
      calibration.attribute("of", std::string("the nominal cask's free rocking at the ensemble's time step: its "
                                              "restitution against its damping ratio, made monotone; each "
                                              "realisation's restitution maps to its damping ratio through it"));
    }

    if (limit_states) write_limit_states(root, plan, *limit_states);
    return hdf5::file_image(root);
  }
}

}  // namespace

void write_ensemble_file(const std::filesystem::path& file, const EnsemblePlan& plan, const EnsembleResults& results,
                         const RunInformation& run, const std::vector<LimitStateSummary>* limit_states) {
  // A failed write leaves the previous checkpoint, with every realisation it holds.
  hdf5::replace_sealed(file, [&] { return result_image(file, plan, results, run, limit_states); });
}


EnsembleResults read_ensemble_results(const std::filesystem::path& file, const EnsemblePlan& plan, double* wall_seconds) {
  EnsembleResults results(plan);
  hdf5::check_seal(file, kResultFile);
  try {
    hdf5::Group root = hdf5::open_file(file);
    if (root.string_attribute("ensemble_toml") != plan.spec().toml_text) {
      throw InputError(located(file, 0, "was written for a different ensemble file (or the file has changed since): "
                                        "cannot resume it with " + plan.spec().file.string()));
    }
    if (root.integer_attribute("realisations") != results.size) {
      throw InputError(located(file, 0, "holds a different number of realisations: cannot resume"));
    }
    if (wall_seconds) *wall_seconds = root.double_attribute("wall_time_s");
    read_realisations(file, root, results);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const InputError*>(&e)) throw;
    throw InputError(located(file, 0, std::string("cannot resume from it: ") + e.what()));
  }
  return results;
}

void check_result_file_seal(const std::filesystem::path& file) { hdf5::check_seal(file, kResultFile); }

void verify_ensemble_file(const std::filesystem::path& file) {
  EnsembleResults results;
  hdf5::check_seal(file, kResultFile);
  try {
    const hdf5::Group root = hdf5::open_file(file);
    read_realisations(file, root, results);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const InputError*>(&e)) throw;
    throw InputError(located(file, 0, std::string(e.what()) + "; expected " + kResultFile));
  }
}

}  // namespace caskdem
