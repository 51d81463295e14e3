#pragma once
// SI inside, conversions at the edges. Every quantity the program computes with is in
// SI units (m, kg, s, N, Pa, rad). Users write other units in case files and records
// (gal, g, cm, bar/cm, t, Hz, degrees); these named helpers are the only place where
// those units turn into SI. src/core/quantity.h parses "2.38e3 bar/cm"-style strings
// with the same factors.

#include <numbers>

namespace caskdem::units {

// Standard gravity (CGPM 1901), the "g" of accelerograms and of the similarity law.
inline constexpr double standard_gravity = 9.80665;  // m/s^2

// Acceleration.
inline constexpr double gal = 0.01;  // 1 gal = 1 cm/s^2, in m/s^2
constexpr double gal_to_si(double a_gal) { return a_gal * gal; }
constexpr double si_to_gal(double a) { return a / gal; }
constexpr double g_to_si(double a_g) { return a_g * standard_gravity; }
constexpr double si_to_g(double a) { return a / standard_gravity; }

// Length and velocity.
inline constexpr double centimetre = 0.01;  // m
inline constexpr double millimetre = 0.001;  // m
constexpr double cm_to_m(double x_cm) { return x_cm * centimetre; }
constexpr double m_to_cm(double x) { return x / centimetre; }
inline constexpr double kine = 0.01;  // 1 kine = 1 cm/s, in m/s

// Mass and density.
inline constexpr double tonne = 1000.0;  // kg
inline constexpr double gram_per_cm3 = 1000.0;  // kg/m^3

// Pressure and distributed (per unit area) contact stiffness.
inline constexpr double bar = 1.0e5;  // Pa
// 1 bar/cm = 1e5 Pa / 0.01 m = 1e7 N/m^3: the unit of the source paper's Tab. 3.
inline constexpr double bar_per_cm = bar / centimetre;  // N/m^3
constexpr double bar_per_cm_to_si(double k) { return k * bar_per_cm; }
constexpr double si_to_bar_per_cm(double k) { return k / bar_per_cm; }

// Angles and frequency.
inline constexpr double degree = std::numbers::pi / 180.0;  // rad
constexpr double deg_to_rad(double a) { return a * degree; }
constexpr double rad_to_deg(double a) { return a / degree; }
constexpr double hz_to_rad_per_s(double f) { return 2.0 * std::numbers::pi * f; }

}  // namespace caskdem::units
