#pragma once
// Ensemble files (ensembles/*.toml): the cask and contact as in a case file, the uncertain
// parameters and their distributions, the motions, the intensity measure and its stripes,
// the sampling, and the limit states. docs/ensemble-file.md lists every key
// (ensemble_file_keys() below, checked by tests/docs); problems are InputErrors naming the
// file, line and key.

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "casefile/case_file.h"
#include "ensemble/distributions.h"
#include "ensemble/sampling.h"

namespace caskdem {

enum class IntensityMeasure {
  pga,        // peak table acceleration, m/s^2
  pgv,        // peak table velocity, m/s
  pga_ratio,  // PGA / (g tan alpha): uplift starts near 1
  pgv_ratio,  // PGV p / (g tan alpha): the overturning-relevant velocity measure
  sa,         // pseudo-spectral acceleration Sa(T, zeta) of the table motion, m/s^2
};
std::string intensity_name(IntensityMeasure measure);
// A level of the measure (SI inside) as the user reads it: "0.6 g", "40 cm/s", or the ratio.
std::string intensity_text(IntensityMeasure measure, double value);
// That unit ("g", "cm/s", "" for the ratios) and the SI value of one of it.
std::string intensity_display_unit(IntensityMeasure measure);
double intensity_display_unit_to_si(IntensityMeasure measure);

struct LimitState {
  enum class Kind { tip_over, rotation_ratio, sliding };
  Kind kind = Kind::tip_over;
  double threshold = 0.0;  // max |theta| / alpha, or sliding in m
  std::string name;        // "tip_over", "rotation_ratio_0.5", "sliding_0.05m"
};

// The parameters that may vary, in the order of the sampler's dimensions.
inline const std::vector<std::string>& uncertain_parameter_names() {
  // incidence (3D only) last, so that a planar ensemble's dimensions keep their numbers
  static const std::vector<std::string> names = {"friction_static", "friction_kinetic", "friction_decay_speed",
                                                 "restitution",     "mass",             "centre_height",
                                                 "incidence"};
  return names;
}

// An ensemble's step where its file names none: the whole-step slider at f_s = 0.05, the largest
// safety factor whose fragility stays within a quarter of its band of f_s = 0.005's on every
// shipped ensemble (docs/time-step.md, "The ensembles' answer with the spring at a touch"); a
// case keeps the source paper's f_s = 0.01 and half-step slider. [integration] safety_factor
// and slider = "half-step" give the paper's scheme back.
inline constexpr double kEnsembleSafetyFactor = 0.05;
inline constexpr std::int32_t kEnsembleSlider = kWholeStepSlider;

struct EnsembleSpec {
  std::filesystem::path file;
  std::string name;   // file stem
  std::string title;
  std::string toml_text;  // the file as read, stored with the results
  Case base;              // cask, contact, friction, damping, integration, limits, free vibration
  std::vector<MotionSpec> motions;
  std::vector<std::string> motion_names;
  std::map<std::string, Distribution> uncertain;  // by name, among uncertain_parameter_names()
  // Those of `uncertain` that are epistemic (fixed for this cask but unknown): sampled once per
  // outer point, each outer point running every stripe (docs/ensemble-file.md).
  std::set<std::string> epistemic;
  int epistemic_points = 30;
  IntensityMeasure measure = IntensityMeasure::pga;
  // A 3D cask's horizontal pairs are scaled by this measure of the pair's PGA or PGV
  // ([intensity] pair_measure); a single horizontal component by its own peak.
  MotionSpec::PairMeasure pair_measure = MotionSpec::PairMeasure::rotd50;
  double spectral_period = 0.0;         // s, for sa
  double spectral_damping_ratio = 0.05;  // for sa
  std::vector<double> levels;                     // SI (or dimensionless), increasing
  std::int64_t realisations_per_stripe = 0;
  SamplingMethod sampling = SamplingMethod::latin_hypercube;
  std::uint64_t seed = 1;
  std::vector<LimitState> limit_states;
  int bootstrap_replicates = 200;
  double confidence = 0.95;
  int block_lanes = 64;
  double checkpoint_interval = 10.0;  // s of wall time between checkpoints
  std::string device = "auto";        // auto, cpu or cuda: where the realisations run (--device overrides)
  long device_line = 0;               // its line in the file (0: not given)

  bool three_d() const { return base.cask.dimensions == 3; }
  int outer_count() const { return epistemic.empty() ? 1 : epistemic_points; }
  std::int64_t realisations_per_outer_point() const {
    return realisations_per_stripe * static_cast<std::int64_t>(levels.size());
  }
  std::int64_t realisation_count() const { return outer_count() * realisations_per_outer_point(); }
};

EnsembleSpec load_ensemble(const std::filesystem::path& file);
// An ensemble from a parsed document (the Python module's keyword arguments): `file` names it in
// messages and its folder is where relative paths start; `text` is what the result file stores.
EnsembleSpec read_ensemble(const toml::table& document, const std::filesystem::path& file, const std::string& text);

// Every key load_ensemble reads, table by table; reading any other is a program error.
const KeySchema& ensemble_file_keys();

}  // namespace caskdem
