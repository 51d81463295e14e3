// Closed forms of rigid-block rocking: the block's parameters, Housner's restitution, free-rocking
// periods, amplitude decay per impact and the overturning thresholds of pulses.
//
// Sources: Housner, G. W. (1963) "The behavior of inverted pendulum structures during
// earthquakes", BSSA 53(2): the equation of motion, p, e = 1 - 2 b^2 / (I_O/m), the linearised
// period and the pulse thresholds. Yim, Chopra & Penzien (1980), Earthquake Eng Struct Dyn 8:
// the nonlinear equation and the energy argument for the amplitude decay. Zhang & Makris (2001),
// J Eng Mech 127(5): overturning under pulses.
//
// Exact free-rocking period. With E = m g R cos(alpha - |theta|) + I_O theta'^2 / 2 conserved,
// released at rest from theta0:
//   theta'^2 = 2 p^2 [cos(alpha - theta0) - cos(alpha - theta)]
//            = 4 p^2 sin(alpha - (theta0 + theta)/2) sin((theta0 - theta)/2),
// and the quarter period is the integral of dtheta / |theta'| over [0, theta0]. The integrand
// has an inverse square-root singularity at theta0; theta = theta0 cos(psi) removes it:
// dtheta = -theta0 sin(psi) dpsi and (theta0 - theta)/2 = theta0 sin^2(psi/2), so both numerator
// and denominator vanish like psi at psi = 0 and the integrand is smooth on [0, pi/2].
//
// Pulse thresholds: linearise about the pivot, u = theta/alpha, tau = p t, and overturning of the
// free motion after the pulse needs w = u + u' - 1 >= 0 at its end (energy at least that of
// the unstable equilibrium u = 1). w' = w + beta a(tau) with w = -1 at the start of rocking gives
//   rectangular pulse from tau = 0 to p t1: beta (1 - exp(-p t1)) >= 1;
//   half-sine a = sin(Omega tau), rocking from Omega tau = psi (beta sin psi = 1):
//   beta [cos psi + exp(-(pi - psi)/Omega)] >= Omega.

#include "theory/rocking.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

namespace caskdem::theory {

double RigidBlock::size() const { return std::hypot(half_width, centre_height); }

double RigidBlock::slenderness() const { return std::atan2(half_width, centre_height); }

double RigidBlock::frequency_parameter() const {
  return std::sqrt(gravity * size() / inertia_about_pivot_per_mass);
}

RigidBlock RigidBlock::rectangle(double half_width, double half_height) {
  RigidBlock block;
  block.half_width = half_width;
  block.centre_height = half_height;
  // About the centre (2b x 2h): (b^2 + h^2)/3; moved to a corner at distance R: + R^2.
  block.inertia_about_pivot_per_mass = 4.0 / 3.0 * (half_width * half_width + half_height * half_height);
  return block;
}

RigidBlock RigidBlock::cylinder(double radius, double half_height) {
  RigidBlock block;
  block.half_width = radius;
  block.centre_height = half_height;
  // About a diameter through the centre: r^2/4 + (2h)^2/12; moved to a rim point: + r^2 + h^2.
  block.inertia_about_pivot_per_mass = 5.0 / 4.0 * radius * radius + 4.0 / 3.0 * half_height * half_height;
  return block;
}

double housner_restitution(const RigidBlock& block) {
  return 1.0 - 2.0 * block.half_width * block.half_width / block.inertia_about_pivot_per_mass;
}

namespace {

void require_free_rocking_amplitude(const RigidBlock& block, double theta0) {
  if (!(theta0 > 0.0 && theta0 < block.slenderness()))
    throw std::domain_error("free rocking needs 0 < theta0 < alpha");
}

}  // namespace

double free_rocking_period_linearised(const RigidBlock& block, double theta0) {
  require_free_rocking_amplitude(block, theta0);
  return 4.0 / block.frequency_parameter() * std::acosh(1.0 / (1.0 - theta0 / block.slenderness()));
}

double free_rocking_period_exact(const RigidBlock& block, double theta0) {
  require_free_rocking_amplitude(block, theta0);
  const double alpha = block.slenderness();
  const double p = block.frequency_parameter();
  // Integrand in psi (see the top of the file); quadrature nodes are interior, so psi = 0 is never evaluated.
  auto integrand = [&](double psi) {
    const double half_psi_sine = std::sin(0.5 * psi);
    const double theta = theta0 * std::cos(psi);
    const double rate_squared_over_4p2 =
        std::sin(alpha - 0.5 * (theta0 + theta)) * std::sin(theta0 * half_psi_sine * half_psi_sine);
    return theta0 * std::sin(psi) / (2.0 * p * std::sqrt(rate_squared_over_4p2));
  };
  const double quarter = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
      integrand, 0.0, 0.5 * std::numbers::pi, 15, 1e-14);
  return 4.0 * quarter;
}

double amplitude_after_impact(const RigidBlock& block, double restitution, double theta_n) {
  const double alpha = block.slenderness();
  const double amplitude = std::abs(theta_n);
  if (amplitude > alpha) throw std::domain_error("amplitude_after_impact: |theta_n| > alpha overturns, no impact");
  if (!(restitution >= 0.0 && restitution <= 1.0)) throw std::domain_error("amplitude_after_impact: e outside [0, 1]");
  // With D(x) = cos(alpha - x) - cos(alpha) = 2 sin(alpha - x/2) sin(x/2) (no cancellation),
  // D(theta_{n+1}) = e^2 D(theta_n). alpha - acos(...) alone loses the small amplitudes to
  // cancellation (absolute error ~1e-16 rad), so refine it with x = 2 asin(E / (2 sin(alpha - x/2))),
  // a contraction for x < alpha whose result has full relative precision.
  const double energy_after = restitution * restitution * 2.0 * std::sin(alpha - 0.5 * amplitude) *
                              std::sin(0.5 * amplitude);
  double next = alpha - std::acos(std::cos(alpha) + energy_after);
  for (int refinement = 0; refinement < 3; ++refinement)
    next = 2.0 * std::asin(energy_after / (2.0 * std::sin(alpha - 0.5 * next)));
  return next;
}

double rectangular_pulse_overturning_beta(const RigidBlock& block, double pulse_duration) {
  return -1.0 / std::expm1(-block.frequency_parameter() * pulse_duration);
}

double half_sine_overturning_beta(double omega_ratio) {
  if (!(omega_ratio > 0.0)) throw std::domain_error("half_sine_overturning_beta: Omega must be positive");
  // beta cos(psi) = sqrt(beta^2 - 1). The residual is -Omega + exp(-pi/(2 Omega)) < 0 at beta = 1
  // (x exp(-pi x / 2) <= 2/(pi e) < 1 for x = 1/Omega) and > 0 at sqrt(1 + Omega^2).
  auto residual = [omega_ratio](double beta) {
    const double psi = std::asin(1.0 / beta);
    return std::sqrt(beta * beta - 1.0) + beta * std::exp(-(std::numbers::pi - psi) / omega_ratio) - omega_ratio;
  };
  const double low = 1.0;
  const double high = std::sqrt(1.0 + omega_ratio * omega_ratio);
  std::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(residual, low, high, residual(low), residual(high),
                                                         boost::math::tools::eps_tolerance<double>(), iterations);
  return 0.5 * (bracket.first + bracket.second);
}

}  // namespace caskdem::theory
