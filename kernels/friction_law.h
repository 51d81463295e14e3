#pragma once
// The friction law: the coefficient mu that limits a contact's shear force, |F_s| <= mu F_n
// (Mohr-Coulomb without cohesion). The source paper found the kinetic coefficient of a
// steel cask on its floor to fall with sliding velocity (its Fig. 3); four laws cover the
// cases a user meets:
//
//   constant        mu = mu_s
//   static_kinetic  mu = mu_s while the contact sticks, mu_k from the step after it slips
//                   (the spring-slider remembers whether it slipped)
//   exponential     mu(v) = mu_k + (mu_s - mu_k) exp(-|v| / v0)
//                   (mu_s at rest, mu_k at high slip speed; mu_k > mu_s gives a rising law;
//                   Dieterich-type velocity weakening, e.g. Bowden & Tabor, and the form the
//                   source paper fitted to its friction tests)
//   tabulated       mu(|v|) linear between the rows of a measured table, constant beyond
//
// v is the slip velocity of the contact point relative to the floor.

#include <algorithm>
#include <type_traits>

#include "kernels/host_device.h"
#include "kernels/lane.h"
#include "kernels/lane_state.h"
#include "kernels/model.h"
#include "kernels/portable_math.h"

namespace caskdem::kernels {

template <class T>
CASKDEM_HOST_DEVICE inline T tabulated_friction(const Model& model, const T& slip_speed) {
  using lane::broadcast;
  T mu = broadcast<T>(model.friction_table_coefficient[0]);
  for (int row = 1; row < model.friction_table_size; ++row) {
    const double v0 = model.friction_table_speed[row - 1];
    const double v1 = model.friction_table_speed[row];
    const double mu0 = model.friction_table_coefficient[row - 1];
    const double slope = (model.friction_table_coefficient[row] - mu0) / (v1 - v0);
    T v = lane::clamp(slip_speed, broadcast<T>(v0), broadcast<T>(v1));
    T segment = broadcast<T>(mu0) + broadcast<T>(slope) * (v - broadcast<T>(v0));
    // Rows are visited in increasing speed, so the last segment the speed reached wins.
    mu = lane::select(slip_speed >= broadcast<T>(v0), segment, mu);
  }
  // A segment falling to a zero row can round a few ulp below zero; friction never pushes.
  return lane::max(mu, broadcast<T>(0.0));
}

template <FrictionLaw Law, class T>
CASKDEM_HOST_DEVICE inline T friction_coefficient(const Model& model, const LaneParameters<T>& lane_parameters,
                                                  const T& slip_speed, const lane::Mask<T>& was_slipping) {
  if constexpr (Law == FrictionLaw::constant) {
    return lane_parameters.friction_static;
  } else if constexpr (Law == FrictionLaw::static_kinetic) {
    return lane::select(was_slipping, lane_parameters.friction_kinetic, lane_parameters.friction_static);
  } else if constexpr (Law == FrictionLaw::exponential) {
    const T decay = exp_negative(slip_speed * lane_parameters.inverse_decay_speed);
    return lane_parameters.friction_kinetic + (lane_parameters.friction_static - lane_parameters.friction_kinetic) * decay;
  } else {
    return tabulated_friction(model, slip_speed);
  }
}

// A floor under the coefficient: mu(v) >= lowest_friction for every slip speed as the law
// computes it, rounding included. The exact law never goes below the lower of mu_s and mu_k (or
// the table's lowest row); its arithmetic can. A falling law's mu_k + (mu_s - mu_k) e, with
// 0 <= e <= 1 (exp_negative), is at least mu_k exactly; a rising law's, and a table's
// interpolation mu0 + slope (v - v0), are computed with a few roundings of numbers as large as
// the highest coefficient, so each can fall a few ulp of that below the lowest one (mu_s = 1e-6
// against mu_k = 0.5 gives 1e-6 - 2.7e-17). The floor keeps 1e-12 of the highest coefficient
// clear of them (and 1e-300 besides, where that product is too small to count: subnormal
// coefficients), and is never negative.
template <FrictionLaw Law, class T>
CASKDEM_HOST_DEVICE inline T lowest_friction(const Model& model, const LaneParameters<T>& lane_parameters) {
  constexpr double clearance = 1e-12, least_clearance = 1e-300;
  if constexpr (Law == FrictionLaw::tabulated) {
    double lowest = model.friction_table_coefficient[0], highest = lowest;
    for (int row = 1; row < model.friction_table_size; ++row) {
      lowest = std::min(lowest, model.friction_table_coefficient[row]);
      highest = std::max(highest, model.friction_table_coefficient[row]);
    }
    return lane::broadcast<T>(std::max(0.0, lowest - clearance * highest - least_clearance));
  } else {
    const T lowest = lane::min(lane_parameters.friction_static, lane_parameters.friction_kinetic);
    const T highest = lane::max(lane_parameters.friction_static, lane_parameters.friction_kinetic);
    return lane::max(lowest - lane::broadcast<T>(clearance) * highest - lane::broadcast<T>(least_clearance),
                     lane::broadcast<T>(0.0));
  }
}

// The limit mu F_n of a contact's shear force. mu matters only through this limit: with F_n = 0
// (an open contact) it is 0 whatever mu is, and a contact whose forces all stay within a floor
// lowest_friction x F_n > 0 sticks unclipped whatever mu(v) is; for it the floor serves as the
// limit and gives the same forces to the bit (a zero floor would not: it clamps a -0 force to
// +0). holds_within(floor) says, per lane, whether the contact's trial spring force and its
// sticking force (spring and dashpot, the same sum the law forms, bit for bit under
// -ffp-contract=off) are within the floor. The laws that cost an exp or a table search are
// evaluated only when some lane of the batch may slip or be clipped: the same bits, less work
// while the cask stands or rocks on a pivot that holds.
// The slip speed is a value, or a callable that computes it (a square root in 3D) only where
// the law is evaluated.
template <FrictionLaw Law, class T, class SlipSpeed, class HoldsWithin>
CASKDEM_HOST_DEVICE inline T friction_limit(const Model& model, const LaneParameters<T>& lane_parameters,
                                            const SlipSpeed& slip_speed, const lane::Mask<T>& was_slipping,
                                            const T& normal_force, HoldsWithin&& holds_within) {
  if constexpr (Law == FrictionLaw::exponential || Law == FrictionLaw::tabulated) {
    const T zero = lane::broadcast<T>(0.0);
    const T floor = lowest_friction<Law>(model, lane_parameters) * normal_force;
    if (lane::all((holds_within(floor) && floor > zero) || normal_force == zero)) return floor;
  }
  if constexpr (std::is_invocable_v<const SlipSpeed&>) {
    return friction_coefficient<Law>(model, lane_parameters, slip_speed(), was_slipping) * normal_force;
  } else {
    return friction_coefficient<Law>(model, lane_parameters, slip_speed, was_slipping) * normal_force;
  }
}

}  // namespace caskdem::kernels
