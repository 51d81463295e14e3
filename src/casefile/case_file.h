#pragma once
// Case files: one TOML file per analysis (cask, contact, friction, damping, integration,
// limits, motion, output). docs/case-file.md lists every key (case_file_keys() below, checked
// by tests/docs); an unknown key, a wrong unit or an out-of-range value is an InputError naming
// the file, line and key.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "casefile/toml_reader.h"
#include "model/build.h"
#include "motion/component_set.h"
#include "motion/record.h"
#include "motion/synthetic.h"
#include "motion/table_motion.h"

namespace caskdem {

struct MotionSpec {
  enum class Kind { none, sine, pulse, record, synthetic };
  enum class Scaling { factor, target_pga, target_pgv };
  Kind kind = Kind::none;
  // sine
  double amplitude = 0.0;    // m (displacement)
  double frequency = 0.0;    // Hz
  double cycles = 0.0;
  double ramp_cycles = 0.0;
  // pulse
  motion::PulseShape shape = motion::PulseShape::half_sine;
  double pulse_amplitude = 0.0;  // m/s^2
  double pulse_duration = 0.0;   // s
  // record
  std::filesystem::path file;
  motion::ReadOptions read;
  // synthetic (a Kanai-Tajimi accelerogram generated from a seed; then treated as a record)
  motion::SyntheticMotion synthetic;
  Scaling scaling = Scaling::factor;
  double scale = 1.0;            // factor, or target PGA (m/s^2) / PGV (m/s)
  double similarity_scale = 1.0; // N: a prototype motion applied to a 1/N model (time / sqrt(N))
  // A 3D cask's motion: the record's horizontal pair (file is H1) and the station's vertical,
  // read as one set on one time base (motion/component_set.h) and scaled by one factor, which
  // a target_pga or target_pgv sets on the pair's intensity measure; and the direction of H1
  // in the floor plane (from x towards z), for any kind.
  enum class PairMeasure { rotd50, rotd100, geometric_mean };
  std::filesystem::path pair;           // empty: one horizontal component
  std::filesystem::path vertical_file;  // empty: none, or [motion.vertical]
  motion::TailRule tails = motion::TailRule::trim;
  PairMeasure pair_measure = PairMeasure::rotd50;
  double incidence = 0.0;  // rad
  std::string where;             // "case.toml:12", the motion's kind, for error messages
};

// Builds the motion; a record that cannot be read is an InputError naming its file and line.
// *applied_scale, when given, gets the factor the record's accelerations were multiplied by (its
// scale, or what its target_pga or target_pgv took; 1 for sines, pulses and no motion).
std::unique_ptr<motion::TableMotion> make_motion(const MotionSpec& spec, double* applied_scale = nullptr);

struct OutputSpec {
  std::filesystem::path directory;  // default: results/<case name>
  double interval = 1e-3;           // s between history samples
  bool csv = true;
  bool hdf5 = true;
  bool plot = true;
};

struct FreeVibrationSpec {
  double initial_tilt_ratio = 0.5;  // theta0 / alpha of the release
  double duration = 0.0;            // s; 0: long enough for the half-cycles needed
  int ratios = 3;                   // successive peak ratios averaged into the restitution
  std::optional<double> target_restitution;
};

struct CaskDescription {  // what the user gave, for reports
  std::string shape;      // "cylinder" or "polygon"
  int dimensions = 2;     // 3: the cylinder in 3D (model/build3d.h)
  Cylinder cylinder;      // when a cylinder
};

struct Case {
  std::filesystem::path file;
  std::string name;   // file stem
  std::string title;
  CaskDescription cask;
  ModelSpec model;
  RealisationParameters parameters;
  MotionSpec horizontal;
  std::optional<MotionSpec> vertical;
  double duration = 0.0;     // s; 0: motion duration + settle_time
  double settle_time = 2.0;  // s after the motion ends
  bool settle_time_given = false;  // a 3D case run without it runs until the cask is at rest
  double rest_cap = 60.0;    // s after the motion a 3D case run waits for rest at most ([integration] rest_cap)
  bool rest_cap_given = false;
  OutputSpec output;
  FreeVibrationSpec free_vibration;
};

Case load_case(const std::filesystem::path& file);
// A case from a parsed document (the Python module's keyword arguments): `file` names it in
// messages and its folder is where relative paths start.
Case read_case(const toml::table& document, const std::filesystem::path& file);

// Every key load_case reads, table by table; reading any other is a program error.
const KeySchema& case_file_keys();
// The keys of the tables a case file shares with an ensemble file (cask, contact,
// contact.barkan, friction, damping, integration, limits), and of one motion table.
const KeySchema& shared_case_keys();
const std::vector<std::string>& motion_keys();

// The sections a case file shares with an ensemble file and a measured specimen: the cask
// (with its nominal mass properties), contact, friction, damping, integration and limits.
// A 3D cask ([cask] dimensions = 3) is refused unless three_d_allowed (case files only).
void read_cask_and_contact(TableReader& root, Case& c, bool three_d_allowed = false);
// An InputError naming the case file when its cask is 3D: `command` runs the planar model.
void require_planar(const Case& c, const std::string& command);
MotionSpec read_motion(TableReader& table);
// three_d: the table may give a horizontal pair and an incidence (a 3D cask's [motion]).
MotionSpec read_motion(TableReader& table, bool three_d);

}  // namespace caskdem
