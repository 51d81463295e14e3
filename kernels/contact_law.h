#pragma once
// The contact law: one rounded corner of the cask against the floor surface, as a
// spring-slider (Cundall & Strack 1979; Cundall, "Formulation of a three-dimensional
// distinct element model", 1988; UDEC's corner-edge contact).
//
// The corner is an arc of radius r; against the flat floor its contact normal is the floor
// normal n = (0, 1) and the contact point lies under the arc's centre.
//
//   overlap        d = max(0, r - y_c),  y_c the height of the arc centre
//   normal force   F_n = max(0, K_n d - beta K_n v_n)        no tension, dashpot included
//
// Two refinements, both off by default (src/diagnosis/mechanisms.h uses them):
//   soft floor layer  the spring is K_n (s min(d, d0) + max(d - d0, 0)): a layer of stiffness
//                     s K_n over the first d0 of overlap (a grout bed, a rough or worn surface)
//   impact damper     -lambda K_n d v_n added to the normal force (Hunt & Crossley 1975,
//                     J. Appl. Mech. 42(2)): its energy loss per impact grows with the impact
//                     speed, so the restitution falls with it, e ~ 1 - (2/3) lambda v for a
//                     point impact; a rocking impact's cannot fall below the plastic impact's
//                     1 - 2 m R^2 sin^2(alpha) / I_O (Housner 1963)
//   shear spring   F_s* = F_s(previous) - K_s v_s dt         incremental: the spring stretches by the slip
//   Coulomb        slipping if |F_s*| > mu F_n; then the spring force is mu F_n sign(F_s*)
//   shear dashpot  -beta K_s v_s while the contact sticks; a slipping contact transmits
//                  exactly mu F_n, so the applied shear force is clipped to |F_s| <= mu F_n
//
// v_n and v_s are the normal and tangential velocities of the contact point relative to the
// floor. The spring's increment reads v_s at the half step (central differences: the slip from
// t_{n-1} to t_n, or under the whole-step slider the part of it since a touch within the step);
// the dashpots and mu read it at the half step as the source paper does, or at
// the whole step where Model::whole_step_terms asks (kernels/slider.h). beta is the stiffness-proportional
// (Rayleigh) damping coefficient: a damping ratio h at circular frequency omega gives
// beta = 2 h / omega (Clough & Penzien, Dynamics of Structures, eq. 12-37). A corner out of
// contact carries no force and forgets its shear spring.
//
// The normal law is a model form (Model::normal_law). Beside the paper's linear spring-dashpot,
// a Hertz spring with Hunt & Crossley's damper (Hunt & Crossley 1975; Gilardi & Sharf 2002,
// Mech. Mach. Theory 37):
//   F_n = max(0, K d sqrt(d/d_H) (1 - lambda v_n))
// The spring is K_H d^(3/2) with K_H = K / sqrt(d_H): it pushes as the linear one does at
// d = d_H (Model::hertz_overlap), stiffens as the contact grows and starts from zero stiffness,
// so the force rises continuously at touch and falls to zero at separation. Its energy is
// (2/5) K d^2 sqrt(d/d_H). All its damping is Hunt & Crossley's damper lambda F_spring v_n,
// proportional to the spring force: the lane's impact_damping, which under this law also
// carries the paper's damping (model/build.h, hunt_crossley_damper: beta K_t at rest, K_t the
// tangent stiffness, becomes lambda m g). In a normal impact at speed u_in it loses exactly what
// makes the rebound speed u_out solve
//   G(-u_out) = G(u_in),   G(u) = u / lambda - ln(1 + lambda u) / lambda^2
// (m u du / (1 + lambda u) = -K_H d^(3/2) dd integrated from touch to separation), so
// e = u_out / u_in ~ 1 - (2/3) lambda u_in, independent of the stiffness.
// The soft floor layer multiplies the spring by its bilinear factor under either law.
//
// Under the Hertz law the shear spring is Mindlin's (Mindlin 1949, "Compliance of elastic
// bodies in contact", J. Appl. Mech. 16; the Hertz-Mindlin pair of DEM codes, e.g. Di Renzo &
// Di Maio 2004, Chem. Eng. Sci. 59): a Hertzian contact's tangential stiffness 8 G* a and its
// normal tangent stiffness 2 E* a both grow with the contact radius a = sqrt(R d), so their
// ratio is the same at every overlap. Here the shear stiffness is K_s (3/2) sqrt(d/d_H), which
// keeps the linear law's K_s / K_n against the normal spring's tangent (3/2) K sqrt(d/d_H).
// A linear shear spring beside a Hertz normal one is stiff where the normal spring is soft,
// as a contact closes and opens, and slips there on a rocking impact: on a cylinder's
// distributed footprint that slip lost a fifth more energy per impact than a base whose
// friction follows its pressure (docs/model.md, "The normal law as a model form"). The 2D
// corner stores K_s times the spring's stretch and pushes with the stiffness of the present
// overlap (the tangential history of DEM codes' Hertz-Mindlin models), so the force falls with
// the stiffness as the contact opens; the 3D cask's springs keep their rule for a stiffness
// that changes (kernels/step3d.h, shear_contact: scaled down as it falls).

#include "kernels/friction_law.h"
#include "kernels/host_device.h"
#include "kernels/lane.h"
#include "kernels/lane_state.h"
#include "kernels/model.h"
#include "kernels/slider.h"

namespace caskdem::kernels {

template <class T>
struct CornerContact {
  T normal_force;   // on the cask, along +y
  T shear_force;    // on the cask, along +x
  CornerState<T> next;  // spring-slider state after this step
};

// The normal force of a contact point from its gap (negative: overlap) and normal velocity:
// spring (with the soft layer) and dashpots, never pulling. Shared by the 2D corners and the 3D
// cask's contact points (kernels/step3d.h).
template <class T>
CASKDEM_HOST_DEVICE inline T normal_force(const Model& model, const T& normal_stiffness,
                                          const LaneParameters<T>& lane_parameters, const T& gap,
                                          const T& normal_velocity) {
  using lane::broadcast;
  using lane::select;
  const T zero = broadcast<T>(0.0);
  const auto touching = gap < zero;
  const T overlap = select(touching, -gap, zero);
  const T layer = lane_parameters.floor_soft_depth;
  const T spring_extension =
      lane_parameters.floor_soft_ratio * lane::min(overlap, layer) + lane::max(overlap - layer, zero);
  // The law is the model's, the same for every lane and thread: a uniform branch.
  if (model.normal_law == NormalLaw::hunt_crossley) {
    const T hertz = lane::sqrt(overlap / broadcast<T>(model.hertz_overlap));  // sqrt(d / d_H)
    const T spring_force = normal_stiffness * spring_extension * hertz;
    const T damping_force = lane_parameters.impact_damping * spring_force * normal_velocity;
    // No tension, as for the linear law.
    return select(touching, lane::max(spring_force - damping_force, zero), zero);
  }
  const T spring_force = normal_stiffness * spring_extension;
  const T damping_force =
      (lane_parameters.damping_beta + lane_parameters.impact_damping * overlap) * normal_stiffness * normal_velocity;
  // No tension: the spring and the dashpots together may push but never pull.
  return select(touching, lane::max(spring_force - damping_force, zero), zero);
}

// Whether every lane has the paper's linear floor: the linear law, no soft layer (s = 1,
// d0 = 0) and no impact damper. There normal_force reduces to max(K_n d - beta K_n v_n, 0) to
// the bit (s min(d, 0) is +0 and max(d - 0, 0) is d; beta + 0 d is beta), which
// linear_normal_force computes with fewer operations: the 3D rim evaluates the law at 16 nodes a step.
// linear_floor_lanes says it lane by lane (the 3D rim's closed form, kernels/rim_forces.h).
template <class T>
CASKDEM_HOST_DEVICE inline auto linear_floor_lanes(const Model& model, const LaneParameters<T>& lane_parameters) {
  const T zero = lane::broadcast<T>(0.0);
  // The law is the model's, for every lane: under another law no lane matches (s > 0 is never -1).
  return lane_parameters.floor_soft_ratio == lane::broadcast<T>(model.normal_law == NormalLaw::linear ? 1.0 : -1.0) &&
         lane_parameters.floor_soft_depth == zero && lane_parameters.impact_damping == zero;
}

template <class T>
CASKDEM_HOST_DEVICE inline bool linear_floor(const Model& model, const LaneParameters<T>& lane_parameters) {
  return lane::all(linear_floor_lanes(model, lane_parameters));
}

template <class T>
CASKDEM_HOST_DEVICE inline T linear_normal_force(const T& normal_stiffness, const T& damping_beta, const T& gap,
                                                 const T& normal_velocity) {
  using lane::select;
  const T zero = lane::broadcast<T>(0.0);
  const auto touching = gap < zero;
  const T overlap = select(touching, -gap, zero);
  const T damping_force = damping_beta * normal_stiffness * normal_velocity;
  return select(touching, lane::max(normal_stiffness * overlap - damping_force, zero), zero);
}

// Mindlin's factor on the shear spring's stiffness under the Hertz law, (3/2) sqrt(d/d_H)
// (above); zero out of contact. Only called under that law.
template <class T>
CASKDEM_HOST_DEVICE inline T mindlin_factor(const Model& model, const T& gap) {
  const T overlap = lane::max(-gap, lane::broadcast<T>(0.0));
  return lane::broadcast<T>(1.5) * lane::sqrt(overlap / lane::broadcast<T>(model.hertz_overlap));
}

// A shear spring's stiffness at a gap under the model's law: K_s under the linear law, Mindlin's
// K_s (3/2) sqrt(d/d_H) under the Hertz law (the 3D rim's nodes and the base centre).
template <class T>
CASKDEM_HOST_DEVICE inline T shear_stiffness_at(const Model& model, const T& shear_stiffness, const T& gap) {
  // The law is the model's, the same for every lane and thread: a uniform branch.
  if (model.normal_law == NormalLaw::hunt_crossley) return shear_stiffness * mindlin_factor(model, gap);
  return shear_stiffness;
}

template <FrictionLaw Law, class T>
CASKDEM_HOST_DEVICE inline CornerContact<T> corner_contact(const Model& model, const LaneParameters<T>& lane_parameters,
                                                           int corner, const T& gap,
                                                           const SliderVelocities<T>& velocity,
                                                           const CornerState<T>& previous) {
  using lane::broadcast;
  using lane::select;
  const T zero = broadcast<T>(0.0);
  const T normal_stiffness = broadcast<T>(model.corner_normal_stiffness[corner]) * lane_parameters.stiffness_scale;
  const T shear_stiffness = broadcast<T>(model.corner_shear_stiffness[corner]) * lane_parameters.stiffness_scale;
  const T beta = lane_parameters.damping_beta;

  const auto touching = gap < zero;
  const T normal = normal_force(model, normal_stiffness, lane_parameters, gap, velocity.normal_dashpot);

  const auto was_slipping = previous.slipping > broadcast<T>(0.5);
  // K_s times the spring's stretch: the force itself under the linear law, which the Hertz law
  // multiplies by Mindlin's factor of the present overlap (the law is the model's: a uniform branch).
  const bool hertz = model.normal_law == NormalLaw::hunt_crossley;
  const T stretch_time = spring_stretch_time(model, lane::max(-gap, zero), velocity.spring.normal);
  const T stretch = previous.shear_spring - shear_stiffness * velocity.spring.slip_x * stretch_time;
  T trial = stretch, sticking_stiffness = shear_stiffness, mindlin = zero;
  if (hertz) {
    mindlin = mindlin_factor(model, gap);
    trial = stretch * mindlin;
    sticking_stiffness = shear_stiffness * mindlin;
  }
  const T sticking_dashpot = -beta * sticking_stiffness * velocity.shear_dashpot_x;
  const T sticking = trial + sticking_dashpot;
  const T limit =
      friction_limit<Law>(model, lane_parameters, lane::abs(velocity.friction_x), was_slipping, normal,
                          [&](const T& floor) { return lane::abs(trial) <= floor && lane::abs(sticking) <= floor; });
  const auto slipping = touching && (lane::abs(trial) > limit);
  // Both branches computed, blended per lane: slip caps the spring at mu F_n, stick keeps
  // the trial force, an open contact resets it.
  const T spring = select(slipping, lane::copysign(limit, trial), select(touching, trial, zero));
  const T dashpot = select(touching && !slipping, sticking_dashpot, zero);
  const T shear_force = lane::clamp(spring + dashpot, -limit, limit);
  T kept = spring;
  if (hertz) {
    // The spring keeps its stretch (times K_s): the force over Mindlin's factor, positive where
    // a slipping contact touches.
    kept = select(slipping, lane::copysign(limit / select(slipping, mindlin, broadcast<T>(1.0)), trial),
                  select(touching, stretch, zero));
  }
  return {normal, shear_force, {kept, lane::as_number<T>(slipping)}};
}

}  // namespace caskdem::kernels
