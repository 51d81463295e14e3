#include "diagnosis/fitting.h"

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <thread>

#include <Eigen/Dense>
#include <nlopt.hpp>

#include "ensemble/sampling.h"

namespace caskdem::diagnosis {

double to_unit(const Parameter& p, double value) {
  const double u = p.logarithmic ? std::log(value / p.low) / std::log(p.high / p.low) : (value - p.low) / (p.high - p.low);
  return std::clamp(u, 0.0, 1.0);
}

double from_unit(const Parameter& p, double unit) {
  unit = std::clamp(unit, 0.0, 1.0);
  return p.logarithmic ? p.low * std::pow(p.high / p.low, unit) : p.low + unit * (p.high - p.low);
}

bool at_search_bound(const Parameter& p, double value) {
  const double u = to_unit(p, value);
  return u <= 1e-6 || u >= 1.0 - 1e-6;
}

std::optional<double> standard_error_of(const FitResult& fit, const std::vector<Parameter>& space, std::size_t i) {
  if (fit.standard_error.empty() || at_search_bound(space[i], fit.best[i])) return std::nullopt;
  return fit.standard_error[i];
}

namespace {

// d(physical)/d(unit) at a value.
double unit_slope(const Parameter& p, double value) {
  return std::abs(p.logarithmic ? value * std::log(p.high / p.low) : p.high - p.low);
}

// Gathers the points the searches ask for until every running search waits, then evaluates
// them as one population. The order of a population is the order of the searches, so the
// run is the same whatever the threads' timing.
class Lockstep {
 public:
  Lockstep(int searches, const std::vector<Parameter>& space, const PopulationObjective& objective)
      : space_(space), objective_(objective), running_(searches), requests_(searches), answers_(searches) {}

  double evaluate(int search, const std::vector<double>& unit) {
    std::unique_lock<std::mutex> lock(mutex_);
    requests_[search] = unit;
    answers_[search].reset();
    ready_.notify_all();
    answered_.wait(lock, [&] { return answers_[search].has_value(); });
    return *answers_[search];
  }

  void finished() {
    std::lock_guard<std::mutex> lock(mutex_);
    --running_;
    ready_.notify_all();
  }

  // Runs on the calling thread until every search has finished.
  void serve(int& evaluations, int& populations) {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      ready_.wait(lock, [&] { return running_ == 0 || waiting() == running_; });
      if (running_ == 0) return;
      std::vector<int> who;
      std::vector<std::vector<double>> points;
      for (int s = 0; s < static_cast<int>(requests_.size()); ++s) {
        if (!requests_[s]) continue;
        who.push_back(s);
        std::vector<double> x(space_.size());
        for (std::size_t i = 0; i < space_.size(); ++i) x[i] = from_unit(space_[i], (*requests_[s])[i]);
        points.push_back(std::move(x));
      }
      lock.unlock();
      std::vector<double> values;
      try {
        values = objective_(points);
      } catch (...) {
        failure_ = std::current_exception();
        values.assign(points.size(), std::numeric_limits<double>::infinity());
      }
      lock.lock();
      evaluations += static_cast<int>(points.size());
      ++populations;
      for (std::size_t k = 0; k < who.size(); ++k) {
        requests_[who[k]].reset();
        answers_[who[k]] = std::isfinite(values[k]) ? values[k] : std::numeric_limits<double>::max();
      }
      answered_.notify_all();
    }
  }

  std::exception_ptr failure() const { return failure_; }

 private:
  int waiting() const {
    int count = 0;
    for (const auto& r : requests_) count += r.has_value();
    return count;
  }
  const std::vector<Parameter>& space_;
  const PopulationObjective& objective_;
  std::mutex mutex_;
  std::condition_variable ready_, answered_;
  int running_;
  std::vector<std::optional<std::vector<double>>> requests_;
  std::vector<std::optional<double>> answers_;
  std::exception_ptr failure_;
};

struct SearchResult {
  std::vector<double> unit;
  double value = std::numeric_limits<double>::infinity();
};

// Standard errors from the curvature of J at the optimum (central differences in unit
// coordinates, one population).
void curvature_errors(const std::vector<Parameter>& space, FitResult& result, const PopulationObjective& objective,
                      int residual_count) {
  const int n = static_cast<int>(space.size());
  std::vector<double> centre(n);
  for (int i = 0; i < n; ++i) centre[i] = to_unit(space[i], result.best[i]);
  const double h = 0.02;
  // Keep the stencil inside the box.
  for (double& c : centre) c = std::clamp(c, h, 1.0 - h);
  std::vector<std::vector<double>> units = {centre};
  for (int i = 0; i < n; ++i) {
    for (int s : {1, -1}) {
      units.push_back(centre);
      units.back()[i] += s * h;
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int si : {1, -1}) {
        for (int sj : {1, -1}) {
          units.push_back(centre);
          units.back()[i] += si * h;
          units.back()[j] += sj * h;
        }
      }
    }
  }
  std::vector<std::vector<double>> points;
  for (const auto& u : units) {
    std::vector<double> x(n);
    for (int i = 0; i < n; ++i) x[i] = from_unit(space[i], u[i]);
    points.push_back(std::move(x));
  }
  const std::vector<double> value = objective(points);
  result.evaluations += static_cast<int>(points.size());
  ++result.populations;
  Eigen::MatrixXd hessian(n, n);
  for (int i = 0; i < n; ++i) hessian(i, i) = (value[1 + 2 * i] - 2.0 * value[0] + value[2 + 2 * i]) / (h * h);
  int k = 1 + 2 * n;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const double pp = value[k], pm = value[k + 1], mp = value[k + 2], mm = value[k + 3];
      hessian(i, j) = hessian(j, i) = (pp - pm - mp + mm) / (4.0 * h * h);
      k += 4;
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(hessian);
  if (eigen.info() != Eigen::Success || eigen.eigenvalues().minCoeff() <= 0.0) {
    result.uncertainty_note = "the objective's curvature at the optimum is not positive definite (a parameter the "
                              "tests do not determine, or a rugged objective): no standard errors";
    return;
  }
  // The residual variance at the optimum (the stencil's centre moves inside the box near a bound).
  const double variance = result.objective / std::max(1, residual_count - n);
  const Eigen::MatrixXd covariance = 2.0 * variance * hessian.inverse();
  for (int i = 0; i < n; ++i) {
    result.standard_error.push_back(unit_slope(space[i], result.best[i]) * std::sqrt(covariance(i, i)));
  }
  result.uncertainty_method = "curvature";
}


// The explored points (indices, in `order`: the first point, then best first) that start the
// searches: the first point; each point with no better explored point within `radius`; then
// the best points not yet chosen.
std::vector<int> basin_starts(const std::vector<std::vector<double>>& explored, const std::vector<int>& order,
                              double radius, int searches) {
  const std::size_t wanted = std::min<std::size_t>(searches, order.size());
  std::vector<int> chosen = {order[0]};
  auto near = [&](int a, int b) {
    double squared = 0.0;
    for (std::size_t i = 0; i < explored[a].size(); ++i) squared += (explored[a][i] - explored[b][i]) * (explored[a][i] - explored[b][i]);
    return squared < radius * radius;
  };
  for (std::size_t k = 1; k < order.size() && chosen.size() < wanted; ++k) {
    bool best_near = true;
    for (std::size_t b = 0; b < k && best_near; ++b) best_near = !near(order[k], order[b]);
    if (best_near) chosen.push_back(order[k]);
  }
  for (std::size_t k = 1; k < order.size() && chosen.size() < wanted; ++k) {
    if (std::find(chosen.begin(), chosen.end(), order[k]) == chosen.end()) chosen.push_back(order[k]);
  }
  return chosen;
}

// One round: explore (one population), then local searches from the explored points that
// basin_starts picks.
// The last `searched_also` explored points each start one more search, after the chosen ones:
// the others' choice and ends are what they would be without them, and `own_best` (if given)
// is the best the round would return without them, to the bit.
SearchResult explore_and_search(const std::vector<Parameter>& space, const std::vector<std::vector<double>>& explored,
                                const PopulationObjective& objective, const FitOptions& options, int searches,
                                FitResult& result, int searched_also = 0, SearchResult* own_best = nullptr) {
  const int n = static_cast<int>(space.size());
  std::vector<double> explored_values;
  {
    std::vector<std::vector<double>> points;
    for (const auto& u : explored) {
      std::vector<double> x(n);
      for (int i = 0; i < n; ++i) x[i] = from_unit(space[i], u[i]);
      points.push_back(std::move(x));
    }
    explored_values = objective(points);
    result.evaluations += static_cast<int>(points.size());
    ++result.populations;
  }
  // The first point always starts a search (a nested model's search then cannot end worse than
  // the model it extends); then, best first, each point with no better one within the basin
  // radius; then the best points left.
  std::vector<int> order(explored.size() - static_cast<std::size_t>(searched_also));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin() + 1, order.end(), [&](int a, int b) { return explored_values[a] < explored_values[b]; });
  std::vector<int> chosen = basin_starts(explored, order, options.basin_radius, searches);
  for (int k = static_cast<int>(order.size()); k < static_cast<int>(explored.size()); ++k) chosen.push_back(k);
  std::vector<std::vector<double>> starts;
  for (int c : chosen) starts.push_back(explored[c]);

  Lockstep lockstep(static_cast<int>(starts.size()), space, objective);
  std::vector<SearchResult> ends(starts.size());
  std::vector<std::thread> threads;
  for (int s = 0; s < static_cast<int>(starts.size()); ++s) {
    threads.emplace_back([&, s] {
      try {
        nlopt::opt search(options.method, static_cast<unsigned>(n));
        search.set_lower_bounds(std::vector<double>(n, 0.0));
        search.set_upper_bounds(std::vector<double>(n, 1.0));
        search.set_maxeval(options.evaluations);
        search.set_xtol_abs(1e-4);
        search.set_initial_step(std::vector<double>(n, options.initial_step));
        // NLopt calls back with a plain function pointer; the context names the search.
        std::pair<Lockstep*, int> context{&lockstep, s};
        struct Bridge {
          static double call(unsigned count, const double* u, double*, void* data) {
            auto* c = static_cast<std::pair<Lockstep*, int>*>(data);
            return c->first->evaluate(c->second, std::vector<double>(u, u + count));
          }
        };
        search.set_min_objective(Bridge::call, &context);
        std::vector<double> u = starts[s];
        double value = explored_values[chosen[s]];
        try {
          search.optimize(u, value);
        } catch (const nlopt::roundoff_limited&) {
          // The search stopped on rounding: its last point stands.
        } catch (const std::runtime_error&) {
          // NLopt reports a generic failure on noisy objectives at times; its point stands.
        }
        ends[s] = {u, value};
      } catch (...) {
        // A search that could not run leaves its start as its end (value infinite).
      }
      lockstep.finished();
    });
  }
  lockstep.serve(result.evaluations, result.populations);
  for (std::thread& t : threads) t.join();
  if (lockstep.failure()) std::rethrow_exception(lockstep.failure());
  // The best explored point counts too: a search never returns worse than it started, but
  // an explored point outside the searches' starts may be better than every end. The points
  // searched also come last in both lists, so the best of the first `own` of each is the round
  // without them.
  auto best_of = [&](std::size_t own_ends, std::size_t own_explored) {
    SearchResult best = *std::min_element(ends.begin(), ends.begin() + static_cast<std::ptrdiff_t>(own_ends),
                                          [](const SearchResult& a, const SearchResult& b) { return a.value < b.value; });
    const auto explored_best =
        std::min_element(explored_values.begin(), explored_values.begin() + static_cast<std::ptrdiff_t>(own_explored)) -
        explored_values.begin();
    if (explored_values[explored_best] < best.value) best = {explored[explored_best], explored_values[explored_best]};
    return best;
  };
  if (own_best) *own_best = best_of(ends.size() - static_cast<std::size_t>(searched_also), order.size());
  return best_of(ends.size(), explored.size());
}

}  // namespace

FitResult fit_parameters(const std::vector<Parameter>& space, const std::vector<std::vector<double>>& references,
                         const PopulationObjective& objective, const FitOptions& options, int residual_count,
                         const std::vector<std::vector<double>>& searched_also) {
  const int n = static_cast<int>(space.size());
  const int searches = std::max(1, options.starts);
  FitResult result;
  // Round 1: the references, a Latin hypercube of the box, and one near the references.
  std::vector<std::vector<double>> explored;
  for (const std::vector<double>& reference : references) {
    std::vector<double> u(n);
    for (int i = 0; i < n; ++i) u[i] = to_unit(space[i], reference[i]);
    explored.push_back(u);
  }
  {
    const int samples = std::max(searches, options.exploration) - static_cast<int>(references.size());
    const int global = std::max(1, samples / 2), local = std::max(1, samples - global);
    const Sampler everywhere(SamplingMethod::latin_hypercube, options.seed, 1, global, n);
    const Sampler nearby(SamplingMethod::latin_hypercube, options.seed + 1, 1, local, n);
    std::vector<double> u(n);
    for (int s = 0; s < global; ++s) {
      for (int i = 0; i < n; ++i) u[i] = everywhere.uniform(0, s, i);
      explored.push_back(u);
    }
    const std::size_t first_references = references.size();
    for (int s = 0; s < local; ++s) {
      const std::vector<double> around = explored[s % first_references];
      for (int i = 0; i < n; ++i) {
        const double v = nearby.uniform(0, s, i);
        u[i] = space[i].mechanism ? v : std::clamp(around[i] + options.local_spread * (2.0 * v - 1.0), 0.0, 1.0);
      }
      explored.push_back(u);
    }
  }
  for (const std::vector<double>& start : searched_also) {
    std::vector<double> u(n);
    for (int i = 0; i < n; ++i) u[i] = to_unit(space[i], start[i]);
    explored.push_back(u);
  }
  SearchResult own;  // the first round without the points searched also
  const SearchResult first = explore_and_search(space, explored, objective, options, searches, result,
                                                static_cast<int>(searched_also.size()), &own);

  // Round 2: every parameter moved a little around a first-round best, and searched again.
  auto refine = [&](const SearchResult& from) {
    std::vector<std::vector<double>> around = {from.unit};
    const Sampler nearby(SamplingMethod::latin_hypercube, options.seed + 2, 1, options.refinement, n);
    std::vector<double> u(n);
    for (int s = 0; s < options.refinement; ++s) {
      for (int i = 0; i < n; ++i) {
        u[i] = std::clamp(from.unit[i] + 0.5 * options.local_spread * (2.0 * nearby.uniform(0, s, i) - 1.0), 0.0, 1.0);
      }
      around.push_back(u);
    }
    return explore_and_search(space, around, objective, options, std::max(1, searches / 2), result);
  };
  // Around the fit's own first-round best first, as without the points searched also, so that
  // the fit ends no higher than it would without them; then, where one of their searches ended
  // lowest, around that end too, so that it ends no higher than they do either.
  SearchResult best = own;
  if (options.refinement > 0) {
    const SearchResult again = refine(own);
    if (again.value < best.value) best = again;
  }
  if (first.unit != own.unit) {
    if (first.value < best.value) best = first;
    if (options.refinement > 0) {
      const SearchResult again = refine(first);
      if (again.value < best.value) best = again;
    }
  }

  result.best.resize(n);
  for (int i = 0; i < n; ++i) result.best[i] = from_unit(space[i], best.unit[i]);
  result.objective = best.value;
  if (options.standard_errors) curvature_errors(space, result, objective, residual_count);
  return result;
}

std::vector<SearchEnd> search_from_each(const std::vector<Parameter>& space,
                                        const std::vector<std::vector<double>>& starts, const std::vector<bool>& free,
                                        const PopulationObjective& objective, int evaluations, double initial_step,
                                        FitResult& tally) {
  const std::size_t n = space.size();
  std::vector<std::size_t> moving;
  for (std::size_t i = 0; i < n; ++i) {
    if (free[i]) moving.push_back(i);
  }
  std::vector<std::vector<double>> start_units;
  for (const std::vector<double>& start : starts) {
    std::vector<double> u(n);
    for (std::size_t i = 0; i < n; ++i) u[i] = to_unit(space[i], start[i]);
    start_units.push_back(std::move(u));
  }
  const int searches = static_cast<int>(starts.size());
  Lockstep lockstep(searches, space, objective);
  std::vector<SearchResult> ends(searches);
  std::vector<std::thread> threads;
  for (int s = 0; s < searches; ++s) {
    threads.emplace_back([&, s] {
      // The search's own best point: BOBYQA's returned point is its best, but a search that
      // stops on an error keeps the best it saw.
      SearchResult best{start_units[s], std::numeric_limits<double>::infinity()};
      try {
        struct Context {
          Lockstep* lockstep;
          int search;
          const std::vector<std::size_t>* moving;
          SearchResult* best;
        } context{&lockstep, s, &moving, &best};
        struct Bridge {
          static double call(unsigned count, const double* v, double*, void* data) {
            auto* c = static_cast<Context*>(data);
            std::vector<double> u = c->best->unit;
            for (unsigned k = 0; k < count; ++k) u[(*c->moving)[k]] = v[k];
            const double value = c->lockstep->evaluate(c->search, u);
            if (value < c->best->value) *c->best = {u, value};
            return value;
          }
        };
        if (moving.empty()) {
          (void)Bridge::call(0, nullptr, nullptr, &context);
        } else {
          const unsigned m = static_cast<unsigned>(moving.size());
          nlopt::opt search(nlopt::LN_BOBYQA, m);
          search.set_lower_bounds(std::vector<double>(m, 0.0));
          search.set_upper_bounds(std::vector<double>(m, 1.0));
          search.set_maxeval(evaluations);
          search.set_xtol_abs(1e-4);
          search.set_initial_step(std::vector<double>(m, initial_step));
          search.set_min_objective(Bridge::call, &context);
          std::vector<double> v(m);
          for (unsigned k = 0; k < m; ++k) v[k] = start_units[s][moving[k]];
          double value = 0.0;
          try {
            search.optimize(v, value);
          } catch (const nlopt::roundoff_limited&) {
          } catch (const std::runtime_error&) {
            // NLopt reports a generic failure on noisy objectives at times; the best point seen stands.
          }
        }
      } catch (...) {
        // A search that could not run leaves its start, at an infinite value.
      }
      ends[s] = best;
      lockstep.finished();
    });
  }
  lockstep.serve(tally.evaluations, tally.populations);
  for (std::thread& t : threads) t.join();
  if (lockstep.failure()) std::rethrow_exception(lockstep.failure());
  std::vector<SearchEnd> out;
  for (const SearchResult& end : ends) {
    SearchEnd e;
    for (std::size_t i = 0; i < n; ++i) e.best.push_back(from_unit(space[i], end.unit[i]));
    e.objective = end.value;
    out.push_back(std::move(e));
  }
  return out;
}

void jackknife_errors(const std::vector<Parameter>& space, FitResult& fit,
                      const std::vector<std::vector<double>>& references, const LeaveOneOutObjective& objective,
                      int clusters, FitOptions options) {
  const std::size_t n = space.size();
  // A flat direction (curvature not positive definite) is one the refits need not move along
  // either, so the jackknife cannot stand in for the curvature there.
  if (fit.standard_error.size() != n) return;
  if (clusters < 3) {
    fit.uncertainty_note = "a jackknife needs at least three tests to leave out: standard errors from the curvature";
    return;
  }
  std::vector<std::vector<double>> starts = {fit.best};
  starts.insert(starts.end(), references.begin(), references.end());
  options.standard_errors = false;
  // Each refit's optimum, in unit coordinates.
  std::vector<std::vector<double>> refits;
  for (int t = 0; t < clusters; ++t) {
    const PopulationObjective without = [&](const std::vector<std::vector<double>>& points) { return objective(points, t); };
    const FitResult refit = fit_parameters(space, starts, without, options, 0);
    fit.evaluations += refit.evaluations;
    fit.populations += refit.populations;
    std::vector<double> u(n);
    for (std::size_t i = 0; i < n; ++i) u[i] = to_unit(space[i], refit.best[i]);
    refits.push_back(std::move(u));
  }
  for (std::size_t i = 0; i < n; ++i) {
    double mean = 0.0;
    for (const auto& u : refits) mean += u[i];
    mean /= clusters;
    double sum = 0.0;
    for (const auto& u : refits) sum += (u[i] - mean) * (u[i] - mean);
    const double jackknife = unit_slope(space[i], fit.best[i]) * std::sqrt((clusters - 1.0) / clusters * sum);
    fit.standard_error[i] = std::max(fit.standard_error[i], jackknife);
  }
  fit.uncertainty_method = "larger of the jackknife over " + std::to_string(clusters) + " tests and the curvature";
}

}  // namespace caskdem::diagnosis
