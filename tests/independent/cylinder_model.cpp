// Equations of the cylinder on a distributed footprint.
//
// Body: a solid cylinder, radius r, half-height h, mass m = rho pi r^2 2h, moment of inertia
// about a horizontal diameter through the centre of mass I = m (r^2/4 + h^2/3); about a rim
// point of the base I_O = I + m (r^2 + h^2) (Housner 1963; the rocking-theory note).
//
// Footprint: the base is a disc; in the plane of motion the strip at x (|x| < r) carries the
// chord's area 2 sqrt(r^2 - x^2) dx. The integral over x is taken with x = r sin(phi), which
// turns the chord's square-root edge into the smooth 2 r^2 cos^2(phi) dphi; Gauss-Legendre in
// phi then integrates the footprint's area exactly to rounding and puts more points near the
// rim, where a rocking cask stands. A convex base (camber c) lowers the strip at x by
// c (1 - x^2/r^2); an eccentric centre of mass (offset e) moves the strips by -e in body x.
//
// Contact (Hunt & Crossley 1975, "Coefficient of restitution interpreted as damping in
// vibroimpact", J Appl Mech 42(2)): each strip, at penetration d >= 0 and rate d', carries a
// pressure p = k_h d^n (1 + 1.5 c_h d'), clipped at zero (no tension, no sticking to the
// floor). With c_h constant the loss per impact grows with the impact speed (e ~ 1 - c_h v).
// A soft floor layer replaces d by phi(d) = s^(1/n) min(d, d0) + max(d - d0, 0): a pressure s
// times smaller over the layer, continuous beyond it.
//
// Friction: each strip carries a tangential traction -mu(v) p tanh(v / v_eps), v the strip's
// horizontal slip speed, so that the total is mu times the total normal force when the base
// slides as one and the moment of friction follows the pressure when it rocks. The tanh is
// Coulomb's law made smooth for an adaptive integrator (creep below v_eps stands for stick).
// Stribeck: mu(v) = mu_k + (mu_s - mu_k) exp(-|v| / v_s).
//
// Motion, in the table's frame with table accelerations a_h, a_v:
//   m X'' = sum f_t - m a_h,  m Y'' = sum f_n - m (g + a_v),
//   I theta'' = sum (r_x f_n - r_y f_t) - 2 zeta_w p I_O theta',
// r the strip's arm from the centre of mass, p = sqrt(m g R / I_O), R = sqrt(r^2 + h^2).
#include "cylinder_model.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace independent {

namespace {

// Gauss-Legendre nodes and weights on [-1, 1] (Newton's method on P_n, Golub-Welsch free).
void gauss_legendre(int n, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(n, 0.0);
  weights.assign(n, 0.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double pk = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    nodes[i] = -x;
    nodes[n - 1 - i] = x;
    weights[i] = weights[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
}

}  // namespace

double CaskParameters::mass() const { return density * std::numbers::pi * radius * radius * 2.0 * half_height; }
double CaskParameters::inertia() const { return mass() * (radius * radius / 4.0 + half_height * half_height / 3.0); }
double CaskParameters::pivot_inertia() const { return inertia() + mass() * (radius * radius + half_height * half_height); }
double CaskParameters::housner_frequency() const {
  return std::sqrt(mass() * gravity * std::hypot(radius, half_height) / pivot_inertia());
}
double CaskParameters::slenderness() const { return std::atan(radius / half_height); }
double CaskParameters::footprint_area() const { return std::numbers::pi * radius * radius; }

double flat_settlement(const CaskParameters& p) {
  return std::pow(p.mass() * p.gravity / (p.footprint_area() * p.k_h), 1.0 / p.exponent);
}

void set_standing_stiffness(CaskParameters& p, double stiffness, double zeta) {
  // Settled flat: p_s = m g / A = k_h d_s^n, slope n k_h d_s^(n-1) = n p_s / d_s = stiffness.
  const double ps = p.mass() * p.gravity / p.footprint_area();
  const double ds = p.exponent * ps / stiffness;
  p.k_h = ps / std::pow(ds, p.exponent);
  // Standing vertical mode: K = stiffness A, C = 1.5 c_h p_s A = 1.5 c_h m g, zeta = C / (2 sqrt(K m)).
  const double omega = std::sqrt(stiffness * p.footprint_area() / p.mass());
  p.c_h = 2.0 * zeta * omega / (1.5 * p.gravity);
}

CylinderModel::CylinderModel(const CaskParameters& p) : p_(p) {
  if (p.k_h <= 0.0 || p.quadrature_points < 2) throw std::invalid_argument("cylinder model: no contact stiffness");
  mass_ = p.mass();
  inertia_ = p.inertia();
  pivot_damping_ = 2.0 * p.rocking_damping_ratio * p.housner_frequency() * p.pivot_inertia();
  std::vector<double> t, w;
  gauss_legendre(p.quadrature_points, t, w);
  const double r = p.radius;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double phi = 0.5 * std::numbers::pi * t[i];
    const double x = r * std::sin(phi);
    xi_.push_back(x - p.eccentricity);
    eta_.push_back(-p.half_height - p.camber * (1.0 - x * x / (r * r)));
    area_.push_back(2.0 * r * r * std::cos(phi) * std::cos(phi) * 0.5 * std::numbers::pi * w[i]);
  }
}

double CylinderModel::pressure(double d, double rate) const {
  const double n = p_.exponent;
  double phi = d;
  if (p_.soft_ratio != 1.0) {
    const double soft = std::pow(p_.soft_ratio, 1.0 / n);
    phi = d <= p_.soft_depth ? soft * d : soft * p_.soft_depth + (d - p_.soft_depth);
  }
  const double elastic = p_.k_h * (n == 1.5 ? phi * std::sqrt(phi) : std::pow(phi, n));
  return std::max(0.0, elastic * (1.0 + 1.5 * p_.c_h * rate));
}

double CylinderModel::elastic_energy_density(double d) const {
  return p_.k_h * std::pow(d, p_.exponent + 1.0) / (p_.exponent + 1.0);
}

void CylinderModel::derivative(const State& s, State& ds, double t, const TableInput& input) const {
  const double c = std::cos(s[2]), sn = std::sin(s[2]);
  const double ah = input.horizontal ? input.horizontal(t) : 0.0;
  const double av = input.vertical ? input.vertical(t) : 0.0;
  double fx = -mass_ * ah, fy = -mass_ * (p_.gravity + av), moment = -pivot_damping_ * s[5];
  const double mu_s = p_.mu_static, mu_k = p_.kinetic_ratio * p_.mu_static;
  for (std::size_t i = 0; i < area_.size(); ++i) {
    const double rx = xi_[i] * c - eta_[i] * sn;
    const double ry = xi_[i] * sn + eta_[i] * c;
    const double d = -(s[1] + ry);
    if (d <= 0.0) continue;
    const double vpx = s[3] - s[5] * ry;
    const double vpy = s[4] + s[5] * rx;
    const double pn = pressure(d, -vpy);
    if (pn <= 0.0) continue;
    const double fn = pn * area_[i];
    const double mu = p_.kinetic_ratio == 1.0 ? mu_s : mu_k + (mu_s - mu_k) * std::exp(-std::abs(vpx) / p_.stribeck_speed);
    const double ft = -mu * fn * std::tanh(vpx / p_.regularisation);
    fx += ft;
    fy += fn;
    moment += rx * fn - ry * ft;
  }
  ds[0] = s[3];
  ds[1] = s[4];
  ds[2] = s[5];
  ds[3] = fx / mass_;
  ds[4] = fy / mass_;
  ds[5] = moment / inertia_;
}

CylinderModel::Resultant CylinderModel::contact(const State& s) const {
  State at_rest = s;
  at_rest[3] = at_rest[4] = at_rest[5] = 0.0;
  State ds{};
  CylinderModel still = *this;
  still.pivot_damping_ = 0.0;
  still.p_.gravity = 0.0;  // only the contact's own forces
  still.derivative(at_rest, ds, 0.0, {});
  return {ds[4] * mass_, ds[3] * mass_, ds[5] * inertia_};
}

double CylinderModel::energy(const State& s, double vertical_acceleration) const {
  const double c = std::cos(s[2]), sn = std::sin(s[2]);
  double e = 0.5 * mass_ * (s[3] * s[3] + s[4] * s[4]) + 0.5 * inertia_ * s[5] * s[5] +
             mass_ * (p_.gravity + vertical_acceleration) * s[1];
  for (std::size_t i = 0; i < area_.size(); ++i) {
    const double d = -(s[1] + xi_[i] * sn + eta_[i] * c);
    if (d > 0.0) e += elastic_energy_density(d) * area_[i];
  }
  return e;
}

double CylinderModel::base_centre_x(const State& s) const {
  // The base's geometric centre is at body (-e, -h - c).
  const double xi = -p_.eccentricity, eta = -p_.half_height - p_.camber;
  return s[0] + xi * std::cos(s[2]) - eta * std::sin(s[2]);
}

State CylinderModel::equilibrium(double applied_moment) const {
  // Nested bisections: for a tilt, the height at which the contact carries m g (the normal
  // force falls monotonically with height); then the tilt at which the contact's couple
  // balances the applied one (it falls monotonically with tilt while the cask stands).
  const double weight = mass_ * p_.gravity;
  auto height_for = [&](double theta) {
    double lo = p_.half_height - 0.01, hi = p_.half_height + p_.camber + 0.01;
    for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
      const double mid = 0.5 * (lo + hi);
      (contact({0.0, mid, theta, 0.0, 0.0, 0.0}).normal > weight ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  auto couple = [&](double theta) { return contact({0.0, height_for(theta), theta, 0.0, 0.0, 0.0}).moment + applied_moment; };
  double lo = -0.05, hi = 0.05;
  if (couple(lo) < 0.0 || couple(hi) > 0.0) throw std::runtime_error("cylinder model: no standing equilibrium");
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (couple(mid) > 0.0 ? lo : hi) = mid;
  }
  const double theta = 0.5 * (lo + hi);
  return {0.0, height_for(theta), theta, 0.0, 0.0, 0.0};
}

}  // namespace independent
