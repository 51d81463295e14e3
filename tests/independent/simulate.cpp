// Time integration with Boost.Odeint (Ahnert & Mulansky 2011, "Odeint - solving ordinary
// differential equations in C++", AIP Conf Proc 1389): the Dormand-Prince 5(4) pair with
// step-size control and dense output, so that the 200 Hz samples (and a delayed sensor's
// shifted samples) are read from the continuous solution, not forced onto the step grid.
// The contact's stiffness (a 180 Hz standing mode) and the friction's regularisation set the
// step; the error control keeps the local error within the tolerances.
#include "simulate.h"

#include <algorithm>
#include <cmath>

#include <boost/numeric/odeint.hpp>

namespace independent {

namespace {
struct Fallen {};
}  // namespace

Response simulate(const CylinderModel& model, const TableInput& input, const State& start,
                  const std::vector<double>& times, const IntegratorSettings& settings) {
  namespace odeint = boost::numeric::odeint;
  Response out;
  const double x0 = model.base_centre_x(start);
  auto record = [&](const State& s) {
    out.states.push_back(s);
    out.rotation.push_back(s[2]);
    out.slide.push_back(model.base_centre_x(s) - x0);
  };
  std::size_t first = 0;
  while (first < times.size() && times[first] <= 0.0) {
    record(start);
    ++first;
  }
  if (first == times.size()) return out;
  std::vector<double> grid{0.0};
  grid.insert(grid.end(), times.begin() + static_cast<long>(first), times.end());

  auto rhs = [&](const State& s, State& ds, double t) {
    ++out.steps;
    model.derivative(s, ds, t, input);
  };
  bool skip_origin = true;
  auto observe = [&](const State& s, double) {
    if (skip_origin) {  // t = 0 was added only to start the integration there
      skip_origin = false;
      return;
    }
    record(s);
    if (std::abs(s[2]) > settings.tip_over_angle) throw Fallen{};
  };
  State s = start;
  auto stepper = odeint::make_dense_output(settings.absolute_tolerance, settings.relative_tolerance, settings.max_step,
                                           odeint::runge_kutta_dopri5<State>());
  try {
    odeint::integrate_times(stepper, rhs, s, grid.begin(), grid.end(), 1e-5, observe);
  } catch (const Fallen&) {
    out.tipped_over = true;
    const State last = out.states.back();
    while (out.states.size() < times.size()) record(last);
  }
  return out;
}

}  // namespace independent
