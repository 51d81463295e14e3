#pragma once
// The plan of an ensemble: the shared model, the motions and their intensities, the
// restitution -> damping calibration curve, and, for any realisation index, its stripe,
// motion, scale factor and physical parameters. Everything here is a pure function of the
// ensemble file, so every thread, block and rank sees the same realisations.
//
// Realisation i belongs to outer point o = i / (S n) (S stripes of n realisations; one outer
// point unless some parameters are epistemic), stripe s = (i mod S n) / n at position
// j = i mod n, and uses motion j mod M (the M motions share each stripe equally). The
// motion is scaled so that its intensity measure equals the stripe's level. Epistemic
// parameters are drawn once per outer point (a Latin hypercube over the outer points, or
// Monte Carlo, from a stream of their own); aleatory ones per (outer point, stripe, position),
// each outer point a sample of its own (the sampler sees outer point o's stripe s as stripe
// o S + s, so outer point 0, and an ensemble without epistemic parameters, draw as before).
// Independent inner samples keep each outer point's fit noise its own, which the estimate
// of beta_U takes out (ensemble/epistemic.h); common draws would share it.
//
// A 3D ensemble ([cask] dimensions = 3) shares all of this: its model is the cylinder's
// (model/build3d.h, whose Model carries the friction, step and criteria), each motion is a
// station's components (the pair and the vertical, scaled together by one factor, so that the
// pair's RotD50, RotD100 or geometric mean equals the stripe's level), and each realisation
// draws its incidence, the direction of H1 in the floor plane, like any aleatory parameter.

#include <cstdint>
#include <memory>
#include <vector>

#include "ensemble/ensemble_file.h"
#include "kernels/block.h"
#include "kernels/model.h"
#include "model/build.h"
#include "model/build3d.h"
#include "motion/table_motion.h"

namespace caskdem {

// Free-vibration restitution against damping ratio for the nominal cask, computed once in
// SIMD lanes (one lane per damping ratio, log-spaced), made monotone by isotonic regression,
// and its inverse.
struct CalibrationCurve {
  std::vector<double> damping_ratio;  // increasing
  std::vector<double> restitution;    // decreasing
  double damping_for(double restitution) const;  // linear in (e, ln h); throws std::out_of_range outside
  double lowest() const { return restitution.back(); }
  double highest() const { return restitution.front(); }
};

CalibrationCurve compute_calibration_curve(const Model& model, const ModelSpec& spec,
                                           const RealisationParameters& nominal, const FreeVibrationSpec& free_vibration,
                                           InstructionSet isa, int points);

struct MotionIntensity {
  double pga = 0.0;       // m/s^2 (3D: the pair's measure, [intensity] pair_measure)
  double pgv = 0.0;       // m/s
  double sa = 0.0;        // m/s^2, Sa(T, zeta) when the measure is sa (0 otherwise)
  double duration = 0.0;  // s (of the motion; runs add the settle time)
};

struct RealisationInput {
  std::int64_t index = 0;
  int outer = 0;  // the outer point (epistemic sample); 0 without epistemic parameters
  int stripe = 0;
  int motion = 0;
  double level = 0.0;         // the stripe's intensity level
  double scale_factor = 0.0;  // on the motion's acceleration
  double restitution = 0.0;   // sampled (0 when restitution is not uncertain)
  double incidence = 0.0;     // rad, the direction of H1 (3D)
  RealisationParameters parameters;
};

class EnsemblePlan {
 public:
  EnsemblePlan(const EnsembleSpec& spec, InstructionSet isa);

  const EnsembleSpec& spec() const { return spec_; }
  const Model& model() const { return model_; }
  const ModelSpec& model_spec() const { return model_spec_; }
  // The file's realisations, or the ones given to set_realisations.
  std::int64_t size() const { return chosen_ ? static_cast<std::int64_t>(chosen_->size()) : spec_.realisation_count(); }
  int motion_count() const { return static_cast<int>(motions_.size()); }
  const motion::TableMotion& motion(int m) const { return *motions_[m]; }  // 3D: its H1
  bool three_d() const { return spec_.three_d(); }
  const Model3D& model3d() const { return model3d_; }  // 3D ensembles
  // Component c of motion m (0: H1, 1: H2, 2: the vertical), as read and unscaled; null where
  // the motion has none (a planar motion has only its H1).
  const motion::TableMotion* component(int m, int c) const;
  const MotionIntensity& intensity(int m) const { return intensities_[m]; }
  double run_duration(int m) const;  // motion duration + settle time
  // Empty unless restitution is uncertain or calibrate() was called.
  const CalibrationCurve& calibration() const { return calibration_; }
  bool restitution_uncertain() const { return spec_.uncertain.count("restitution") > 0; }
  // Computes the calibration curve when the file did not need one (a caller's restitutions),
  // as the constructor would have: the same curve, whichever way it came.
  void calibrate(InstructionSet isa);
  // The nominal cask's parameters (the file's, before sampling), and the lightest mass the
  // ensemble's one time step was chosen for.
  const RealisationParameters& nominal() const { return nominal_; }
  double lightest_mass() const { return lightest_mass_; }
  double stability_angle() const { return model_.stability_angle; }
  double frequency_parameter() const { return frequency_parameter_; }  // p of the rigid equivalent
  // N when every motion is a prototype's applied to a 1/N model (its similarity_scale), so that
  // the stripes' intensities are the model's; 1 for a full-size cask; 0 when the motions differ.
  double model_scale() const;

  RealisationInput realisation(std::int64_t index) const;
  int outer_of(std::int64_t index) const {
    return chosen_ ? (*chosen_)[index].outer : static_cast<int>(index / spec_.realisations_per_outer_point());
  }
  // realisation(index).motion, without sampling its parameters.
  int motion_of(std::int64_t index) const {
    if (chosen_) return (*chosen_)[index].motion;
    const std::int64_t position = index % spec_.realisations_per_outer_point() % spec_.realisations_per_stripe;
    return static_cast<int>(position % motion_count());
  }
  // Replaces the file's sampled realisations by a caller's (ensemble/rollout.h, which checks
  // them), realisation i being inputs[i]: every engine runs them as it runs the file's. A copy
  // of a plan shares its motions, so a plan per call of the caller's costs no reading.
  void set_realisations(std::vector<RealisationInput> inputs);
  // The motion's intensity (of the scaled motion as applied) for a given scale factor.
  double intensity_of(int motion, double scale_factor) const;

 private:
  EnsembleSpec spec_;
  ModelSpec model_spec_;
  RealisationParameters nominal_;
  Model model_;
  double lightest_mass_ = 0.0;
  std::vector<std::shared_ptr<const motion::TableMotion>> motions_;
  std::vector<std::shared_ptr<const motion::TableMotion>> second_horizontal_, vertical_;  // 3D
  Model3D model3d_;
  std::vector<MotionIntensity> intensities_;
  CalibrationCurve calibration_;
  Sampler sampler_;
  Sampler outer_sampler_;
  double frequency_parameter_ = 0.0;
  std::shared_ptr<const std::vector<RealisationInput>> chosen_;  // null: the file's
};

}  // namespace caskdem
