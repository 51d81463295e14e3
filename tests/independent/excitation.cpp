#include "excitation.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace independent {

double Accelerogram::operator()(double t) const {
  if (acceleration.empty() || t < 0.0) return 0.0;
  const double u = t / time_step;
  const auto k = static_cast<std::size_t>(u);
  if (k + 1 >= acceleration.size()) return k + 1 == acceleration.size() && u == k ? acceleration.back() : 0.0;
  const double f = u - static_cast<double>(k);
  return (1.0 - f) * acceleration[k] + f * acceleration[k + 1];
}

double Accelerogram::duration() const {
  return acceleration.empty() ? 0.0 : time_step * static_cast<double>(acceleration.size() - 1);
}

double Accelerogram::peak() const {
  double p = 0.0;
  for (double a : acceleration) p = std::max(p, std::abs(a));
  return p;
}

namespace {
// The number after `key` and an '=' in `line` (PEER writes "NPTS=  5372, DT=   .0100 SEC"
// and "NPTS =   7500 , DT =   .020 SEC").
double header_number(const std::string& line, const std::string& key, const std::filesystem::path& file) {
  const auto at = line.find(key);
  const auto eq = at == std::string::npos ? std::string::npos : line.find('=', at);
  if (eq == std::string::npos) throw std::runtime_error(file.string() + ": line 4: no '" + key + "=' in the header");
  return std::stod(line.substr(eq + 1));
}
}  // namespace

Accelerogram read_at2(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  std::string line;
  for (int i = 0; i < 4; ++i)
    if (!std::getline(in, line)) throw std::runtime_error(file.string() + ": fewer than 4 header lines");
  const auto points = static_cast<std::size_t>(header_number(line, "NPTS", file));
  Accelerogram a;
  a.time_step = header_number(line, "DT", file);
  double v = 0.0;
  while (a.acceleration.size() < points && in >> v) a.acceleration.push_back(v * 9.80665);
  if (a.acceleration.size() != points || !(a.time_step > 0.0))
    throw std::runtime_error(file.string() + ": expected " + std::to_string(points) + " values after the header");
  return a;
}

Accelerogram model_scale_window(const Accelerogram& record, double start, double end, double taper, double time_factor,
                                double pga) {
  Accelerogram out;
  out.time_step = record.time_step * time_factor;
  const auto first = static_cast<std::size_t>(std::llround(start / record.time_step));
  const auto last = std::min(record.acceleration.size() - 1, static_cast<std::size_t>(std::llround(end / record.time_step)));
  for (std::size_t k = first; k <= last; ++k) {
    const double to_end = (last - k) * record.time_step;
    const double from_start = (k - first) * record.time_step;
    double w = 1.0;
    if (to_end < taper) w *= 0.5 * (1.0 - std::cos(std::numbers::pi * to_end / taper));
    if (from_start < taper) w *= 0.5 * (1.0 - std::cos(std::numbers::pi * from_start / taper));
    out.acceleration.push_back(w * record.acceleration[k]);
  }
  const double scale = pga / out.peak();
  for (double& v : out.acceleration) v *= scale;
  return out;
}

double ramped_sine_duration(double frequency, double cycles) { return (cycles + 2.0) / frequency; }

std::function<double(double)> ramped_sine(double amplitude, double frequency, double cycles, double phase) {
  const double omega = 2.0 * std::numbers::pi * frequency;
  const double period = 1.0 / frequency;
  const double total = ramped_sine_duration(frequency, cycles);
  return [=](double t) {
    if (t <= 0.0 || t >= total) return 0.0;
    double envelope = 1.0;
    if (t < period) envelope = std::pow(std::sin(0.5 * std::numbers::pi * t / period), 2);
    else if (t > total - period) envelope = std::pow(std::sin(0.5 * std::numbers::pi * (total - t) / period), 2);
    return -amplitude * omega * omega * envelope * std::sin(omega * t + phase);
  };
}

}  // namespace independent
