#pragma once
// The library of model extensions: physical mechanisms the source paper's model leaves out,
// each with its own parameters, implemented in the one step both the deterministic code and
// the ensemble kernel run (kernels/contact_law.h, kernels/step.h), except the sensor delay,
// which belongs to the data, not the cask.
//
//   velocity_dependent_friction     mu_k = r mu_s reached at slip speeds above v0 (exponential law)
//   amplitude_dependent_restitution Hunt-Crossley impact damper lambda: loss grows with impact speed
//   eccentric_mass                  centre of mass e off the axis: rocking is asymmetric
//   base_imperfection               convex base: its middle sits c below its edges
//   vertical_excitation             vertical table acceleration (measured channel, or g_v times the
//                                   horizontal one when none was measured) acting, with gain g
//   floor_compliance                a soft floor layer: stiffness s K over the first d0 of overlap
//   out_of_plane_loss               rocking damper 2 zeta_w p (|theta|/alpha) omega (wobbling, top-spinning)
//   sensor_delay                    the response channels lag the table channel by tau
//
// The baseline model fits the friction coefficient mu (constant law), the damping ratio h
// (the rocking restitution) and a contact stiffness scale k. A model is the baseline plus a
// set of mechanisms; its parameter vector lists the baseline's, then each mechanism's.

#include <optional>
#include <string>
#include <vector>

#include "casefile/case_file.h"
#include "model/build.h"

namespace caskdem::diagnosis {

enum class Mechanism {
  velocity_dependent_friction,
  amplitude_dependent_restitution,
  eccentric_mass,
  base_imperfection,
  vertical_excitation,
  floor_compliance,
  out_of_plane_loss,
  sensor_delay,
};

const std::vector<Mechanism>& all_mechanisms();
std::string mechanism_name(Mechanism mechanism);
std::optional<Mechanism> parse_mechanism(const std::string& name);
// The mechanisms of a list separated by ',' or '+', as a fit's name writes it ("baseline +
// eccentric_mass"); "baseline" and blanks name none. An unknown name is an InputError that
// begins with `where` (the option or key it came from).
std::vector<Mechanism> parse_mechanism_list(const std::string& text, const std::string& where);

struct Parameter {
  std::string name;
  std::string units;
  double low = 0.0, high = 1.0;  // search box
  bool logarithmic = false;      // searched on a log scale (then low > 0)
  double reference = 0.0;        // the value that switches the mechanism off (or the baseline's start)
  bool mechanism = false;        // a mechanism's own parameter (not the baseline's)
  // A mechanism's parameter whose reference alone switches the mechanism off, whatever the
  // others (a kinetic ratio of 1, a gain of 0); false for one that only shapes it (a decay speed).
  bool switches_off = true;
};

// Where the vertical table acceleration of a test comes from.
enum class VerticalSource { none, measured, from_horizontal };

// The specimen's baseline plus a set of mechanisms.
class ModelVariant {
 public:
  ModelVariant(const Case& specimen, std::vector<Mechanism> mechanisms, bool vertical_measured);

  const std::vector<Mechanism>& mechanisms() const { return mechanisms_; }
  bool has(Mechanism m) const;
  std::string name() const;  // "baseline" or "baseline + a + b"
  const std::vector<Parameter>& parameters() const { return parameters_; }
  int size() const { return static_cast<int>(parameters_.size()); }
  int baseline_size() const { return 3; }

  const Model& model() const { return model_; }
  VerticalSource vertical_source() const;
  // What a parameter vector (physical values) means for a realisation, and the delay.
  RealisationParameters realisation(const std::vector<double>& x) const;
  double sensor_delay(const std::vector<double>& x) const;
  // The reference point: baseline parameters from `baseline` (or the specimen), mechanisms off.
  std::vector<double> reference(const std::vector<double>* baseline = nullptr) const;
  // The specimen's nominal baseline parameters.
  std::vector<double> nominal_baseline() const;
  int index_of(const std::string& name) const;  // of a parameter; -1 when absent

 private:
  Case specimen_;
  std::vector<Mechanism> mechanisms_;
  bool vertical_measured_;
  std::vector<Parameter> parameters_;
  Model model_;
};

}  // namespace caskdem::diagnosis
