// Is the planar model conservative for this cask? The same cask under the same stations'
// records at the same intensity stripes, run by the planar model (each horizontal component
// alone, with the vertical) and in 3D (the pair at incidence angles, with the vertical); the
// fragility curves of each side by side with their bands (docs/cask3d.md, "Planar against 3D").
//
//   planar_vs_3d CASE3D.toml [--levels 0.2,0.3,...] (g) [--angles 6] [--replicates 200]
//                [--csv ROWS.csv] [--curves CURVES.csv]
//   planar_vs_3d CASE3D.toml --fs 0.005,0.01,0.02 [--levels ...]
//
// With --fs, the 3D fragility alone at each time-step safety factor on the same realisations
// (one incidence: an axisymmetric cask's response turns with the pair), set against the first:
// the fitted curves, and how many realisations change their outcome.
//
// CASE3D is a 3D case file ([cask] dimensions = 3): its cask, contact, friction, damping and
// limits, and its motion's similarity scale (the records are prototype motions). The records
// are the sets of ../shared/motions/three-component (both horizontals and, where there is one,
// the vertical). At a stripe x (PGA, g):
//   planar  each horizontal component alone scaled to PGA = x, the station's vertical by the
//           same factor: two runs per set, for two planar models of the cylinder (two corners at
//           the gyration half-width, the paper's; a distributed footprint pivoting on the rim);
//   3D      the set scaled by one factor so that the pair's RotD50 PGA = x, at `angles`
//           incidence angles evenly spread over [0, 180) degrees (the stratified uniform).
// Limit states: the tilt beyond alpha / 2 and beyond alpha (alpha each model's own), tip-over.
// The bootstrap resamples the sets, so the bands carry the record-to-record variability.

#include <omp.h>

#include <array>
#include <cmath>
#include <optional>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "casefile/case_file.h"
#include "core/error.h"
#include "ensemble/fragility.h"
#include "model/build.h"
#include "motion/component_set.h"
#include "motion/pair_intensity.h"
#include "sim/case_run3d.h"
#include "sim/simulate.h"

namespace caskdem {
namespace {

constexpr double kG = 9.80665;

struct Station {
  std::string name;
  motion::ComponentSet set;
};

std::vector<Station> stations() {
  const std::filesystem::path dir = std::filesystem::path(CASKDEM_SHARED_DIR) / "motions" / "three-component";
  const std::vector<std::array<std::string, 4>> files = {
      {"El Centro 1940", "elcentro1940_RSN6_H1_180.AT2", "elcentro1940_RSN6_H2_270.AT2", "elcentro1940_RSN6_UP.AT2"},
      {"Kobe 1995 KJMA", "kobe1995_RSN1106_KJMA_H1_000.AT2", "kobe1995_RSN1106_KJMA_H2_090.AT2",
       "kobe1995_RSN1106_KJMA_UP.AT2"},
      {"Northridge 1994 Rinaldi", "northridge1994_RSN1063_Rinaldi_H1_228.AT2", "northridge1994_RSN1063_Rinaldi_H2_318.AT2",
       "northridge1994_RSN1063_Rinaldi_UP.AT2"},
      {"Loma Prieta 1989 Corralitos", "lomaprieta1989_RSN753_Corralitos_H1_000.AT2",
       "lomaprieta1989_RSN753_Corralitos_H2_090.AT2", "lomaprieta1989_RSN753_Corralitos_UP.AT2"},
      {"San Fernando 1971 Pacoima Dam", "sanfernando1971_RSN77_PacoimaDam_H1_164.AT2",
       "sanfernando1971_RSN77_PacoimaDam_H2_254.AT2", "sanfernando1971_RSN77_PacoimaDam_UP_DWN.AT2"},
      {"Manjil 1990 Abbar", "manjil1990_RSN1633_Abbar_H1_L.AT2", "manjil1990_RSN1633_Abbar_H2_T.AT2",
       "manjil1990_RSN1633_Abbar_UP_V.AT2"},
      {"Landers 1992 Lucerne", "landers1992_RSN879_Lucerne_H1_260.AT2", "landers1992_RSN879_Lucerne_H2_345.AT2", ""},
  };
  std::vector<Station> out;
  for (const auto& f : files) {
    const std::optional<std::filesystem::path> up = f[3].empty() ? std::nullopt : std::optional(dir / f[3]);
    out.push_back({f[0], motion::read_component_set(dir / f[1], dir / f[2], up)});
  }
  return out;
}

// Limit states, as fractions of each model's alpha (tip-over: 0).
const std::vector<std::pair<std::string, double>> kLimitStates = {
    {"tilt beyond alpha/2", 0.5}, {"tilt beyond alpha", 1.0}, {"tip-over", 0.0}};

bool exceeds(double ratio, bool tipped, double limit) { return limit > 0.0 ? (tipped || ratio > limit) : tipped; }

struct Outcome {
  double ratio = 0.0;  // max rotation or tilt / alpha
  bool tipped = false;
};

struct Model2D {
  std::string name;
  Model model;
  LaneParameters<double> lane;
};

Model2D planar_model(const Case& c, const std::string& name, HalfWidthRule rule, int footprint_points) {
  Case planar = c;
  planar.cask.dimensions = 2;
  Cylinder cylinder = c.cask.cylinder;
  cylinder.rule = rule;
  cylinder.footprint_points = footprint_points;
  planar.model.section = cylinder_section(cylinder, c.model.section.rounding);
  const RealisationParameters mass = nominal_parameters(planar.model);
  planar.parameters.mass = mass.mass;
  planar.parameters.inertia = mass.inertia;
  planar.parameters.centre_of_mass = mass.centre_of_mass;
  Model2D m{name, build_model(planar.model, planar.parameters), {}};
  m.lane = lane_parameters(m.model, planar.parameters);
  return m;
}

motion::Record prepared(const motion::Record& record, double factor, double similarity) {
  motion::Record r = motion::scaled(record, factor);
  return similarity != 1.0 ? motion::time_scaled(r, 1.0 / std::sqrt(similarity)) : r;
}

std::vector<double> parse_list(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) out.push_back(std::stod(item));
  return out;
}

// The 3D fragility at each safety factor, on the same realisations: one per station and stripe.
int step_study(const Case& c, const std::vector<Station>& sets, const std::vector<double>& levels,
               const std::vector<double>& safety_factors) {
  const Cylinder& cylinder = c.cask.cylinder;
  const CaskSpec3D cask = cask_spec3d(cylinder, c.model.section.rounding, c.parameters.mass);
  const RealisationParameters parameters = nominal_parameters3d(cask, c.parameters);
  const double similarity = c.horizontal.similarity_scale;
  const int count = static_cast<int>(sets.size() * levels.size());
  std::vector<std::vector<Outcome>> outcomes;
  for (double f : safety_factors) {
    ModelSpec spec = c.model;
    spec.safety_factor = f;
    const Model3D model = build_model3d(spec, cask, parameters);
    const LaneParameters<double> lane = lane_parameters3d(model, parameters);
    std::vector<Outcome> out(count);
    const double start = omp_get_wtime();
#pragma omp parallel for schedule(dynamic, 1)
    for (int j = 0; j < count; ++j) {
      const motion::ComponentSet& set = sets[j / levels.size()].set;
      const double factor = levels[j % levels.size()] * kG / motion::pair_intensity(set.h1, set.h2).pga_rotd50;
      const auto h1 = motion::make_record_motion(prepared(set.h1, factor, similarity));
      const auto h2 = motion::make_record_motion(prepared(set.h2, factor, similarity));
      const auto up = set.vertical ? motion::make_record_motion(prepared(*set.vertical, factor, similarity)) : nullptr;
      const RunResult3D r = simulate3d(model, lane, rest_state3d(model, lane), {h1.get(), h2.get(), up.get(), 0.0},
                                       {h1->duration() + c.settle_time, 0.0});
      out[j] = {r.summary.max_tilt_ratio, r.summary.status == LaneStatus::tipped_over};
    }
    std::printf("f_s %.3f (dt %.3g s): %d runs in %.0f s\n", f, model.model.time_step, count, omp_get_wtime() - start);
    outcomes.push_back(std::move(out));
  }
  for (const auto& [limit_name, limit] : kLimitStates) {
    for (std::size_t k = 0; k < safety_factors.size(); ++k) {
      std::vector<std::int64_t> trials(levels.size(), 0), counts(levels.size(), 0);
      int changed = 0;
      for (int j = 0; j < count; ++j) {
        const Outcome& o = outcomes[k][j];
        const Outcome& reference = outcomes[0][j];
        trials[j % levels.size()] += 1;
        const bool exceeded = exceeds(o.ratio, o.tipped, limit);
        counts[j % levels.size()] += exceeded;
        changed += exceeded != exceeds(reference.ratio, reference.tipped, limit);
      }
      const fragility::LognormalFit fit = fragility::fit_lognormal(levels, trials, counts);
      std::printf("%-20s f_s %.3f: median %.3f g, beta %.3f; %d of %d realisations change outcome from f_s %.3f;",
                  limit_name.c_str(), safety_factors[k], fit.median, fit.log_std, changed, count, safety_factors[0]);
      for (std::size_t l = 0; l < levels.size(); ++l) std::printf(" %lld", static_cast<long long>(counts[l]));
      std::printf("\n");
    }
  }
  return 0;
}

int run(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: planar_vs_3d CASE3D.toml [--levels g,...] [--angles N] [--replicates N] [--csv F] [--curves F]\n";
    return 2;
  }
  std::vector<double> levels = {0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.2};
  int angles = 6, replicates = 200;
  std::string csv, curves;
  std::vector<double> safety_factors;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--levels") levels = parse_list(value);
    else if (key == "--angles") angles = std::stoi(value);
    else if (key == "--replicates") replicates = std::stoi(value);
    else if (key == "--csv") csv = value;
    else if (key == "--curves") curves = value;
    else if (key == "--fs") safety_factors = parse_list(value);
    else throw std::invalid_argument("unknown option " + key);
  }
  const Case c = load_case(argv[1]);
  if (c.cask.dimensions != 3) throw std::invalid_argument(std::string(argv[1]) + ": not a 3D case");
  const double similarity = c.horizontal.similarity_scale;
  const std::vector<Station> sets = stations();
  if (!safety_factors.empty()) return step_study(c, sets, levels, safety_factors);

  // The models: 3D from the case, two planar readings of the same cylinder.
  const Cylinder& cylinder = c.cask.cylinder;
  const CaskSpec3D cask = cask_spec3d(cylinder, c.model.section.rounding, c.parameters.mass);
  const RealisationParameters parameters3d = nominal_parameters3d(cask, c.parameters);
  const Model3D model3d = build_model3d(c.model, cask, parameters3d);
  const LaneParameters<double> lane3d = lane_parameters3d(model3d, parameters3d);
  const std::vector<Model2D> planar = {planar_model(c, "planar, corners at the gyration half-width", HalfWidthRule::gyration, 0),
                                       planar_model(c, "planar, distributed footprint", HalfWidthRule::radius,
                                                    kDefaultFootprintPoints)};
  std::printf("alpha: 3D %.4f rad; %s %.4f; %s %.4f\n", model3d.model.stability_angle, planar[0].name.c_str(),
              planar[0].model.stability_angle, planar[1].name.c_str(), planar[1].model.stability_angle);

  // Every run: (model, set, level, variant); variant is the component (planar) or the angle (3D).
  struct Job {
    int model;  // 0, 1 planar; 2 3D
    int set, level, variant;
  };
  std::vector<Job> jobs;
  for (int s = 0; s < static_cast<int>(sets.size()); ++s) {
    for (int l = 0; l < static_cast<int>(levels.size()); ++l) {
      for (int a = 0; a < angles; ++a) jobs.push_back({2, s, l, a});
      for (int m = 0; m < 2; ++m) {
        for (int component = 0; component < 2; ++component) jobs.push_back({m, s, l, component});
      }
    }
  }
  std::vector<Outcome> outcomes(jobs.size());
  const double start = omp_get_wtime();
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    const Job& job = jobs[j];
    const motion::ComponentSet& set = sets[job.set].set;
    const double target = levels[job.level] * kG;
    if (job.model == 2) {
      const double factor = target / motion::pair_intensity(set.h1, set.h2).pga_rotd50;
      const auto h1 = motion::make_record_motion(prepared(set.h1, factor, similarity));
      const auto h2 = motion::make_record_motion(prepared(set.h2, factor, similarity));
      const auto up = set.vertical ? motion::make_record_motion(prepared(*set.vertical, factor, similarity)) : nullptr;
      const double incidence = std::numbers::pi * job.variant / angles;
      const double duration = h1->duration() + c.settle_time;
      const RunResult3D r = simulate3d(model3d, lane3d, rest_state3d(model3d, lane3d),
                                       {h1.get(), h2.get(), up.get(), incidence}, {duration, 0.0});
      outcomes[j] = {r.summary.max_tilt_ratio, r.summary.status == LaneStatus::tipped_over};
    } else {
      const motion::Record& horizontal = job.variant == 0 ? set.h1 : set.h2;
      const double factor = target / motion::peak_ground_acceleration(horizontal);
      const auto h = motion::make_record_motion(prepared(horizontal, factor, similarity));
      const auto up = set.vertical ? motion::make_record_motion(prepared(*set.vertical, factor, similarity)) : nullptr;
      const Model2D& m = planar[job.model];
      const double duration = h->duration() + c.settle_time;
      const RunResult r = simulate(m.model, m.lane, rest_state(m.model, m.lane), {h.get(), up.get()}, {duration, 0.0});
      outcomes[j] = {r.summary.max_rotation_ratio, r.summary.tipped_over};
    }
  }
  std::printf("%zu runs in %.0f s on %d threads\n", jobs.size(), omp_get_wtime() - start, omp_get_max_threads());

  const std::vector<std::string> model_names = {planar[0].name, planar[1].name, "3D, the pair at " + std::to_string(angles) + " angles"};
  std::ofstream rows, curve_rows;
  if (!csv.empty()) {
    rows.open(csv);
    rows << "model,limit_state,pga_g,trials,count,probability,lower,upper,median_g,beta\n";
  }
  if (!curves.empty()) {
    curve_rows.open(curves);
    curve_rows << "model,limit_state,pga_g,probability,lower,upper\n";
  }
  std::vector<double> grid;
  for (double x = 0.05; x <= 2.0001; x += 0.025) grid.push_back(x);
  for (int m = 0; m < 3; ++m) {
    for (const auto& [limit_name, limit] : kLimitStates) {
      fragility::StripeData data;
      data.levels = levels;
      data.trials.assign(sets.size(), std::vector<std::int64_t>(levels.size(), 0));
      data.counts = data.trials;
      for (std::size_t j = 0; j < jobs.size(); ++j) {
        if (jobs[j].model != m) continue;
        data.trials[jobs[j].set][jobs[j].level] += 1;
        data.counts[jobs[j].set][jobs[j].level] += exceeds(outcomes[j].ratio, outcomes[j].tipped, limit) ? 1 : 0;
      }
      const auto stripes = fragility::stripe_probabilities(data, 0.95);
      std::vector<std::int64_t> trials, counts;
      for (const auto& s : stripes) {
        trials.push_back(s.trials);
        counts.push_back(s.count);
      }
      const fragility::LognormalFit fit = fragility::fit_lognormal(levels, trials, counts);
      std::printf("%-45s %-20s median %s g, beta %s;", model_names[m].c_str(), limit_name.c_str(),
                  fit.fitted ? std::to_string(fit.median).substr(0, 5).c_str() : "-",
                  fit.fitted ? std::to_string(fit.log_std).substr(0, 5).c_str() : "-");
      for (const auto& s : stripes) std::printf(" %lld/%lld", static_cast<long long>(s.count), static_cast<long long>(s.trials));
      std::printf("\n");
      if (rows.is_open()) {
        for (const auto& s : stripes) {
          rows << '"' << model_names[m] << "\",\"" << limit_name << "\"," << s.level << ',' << s.trials << ',' << s.count
               << ',' << s.probability << ',' << s.lower << ',' << s.upper << ',' << (fit.fitted ? fit.median : NAN) << ','
               << (fit.fitted ? fit.log_std : NAN) << '\n';
        }
      }
      if (curve_rows.is_open() && fit.fitted) {
        const fragility::Band band = fragility::bootstrap_band(data, grid, replicates, 0.95, 2026);
        for (std::size_t g = 0; g < grid.size(); ++g) {
          curve_rows << '"' << model_names[m] << "\",\"" << limit_name << "\"," << grid[g] << ','
                     << fragility::fragility_probability(fit, grid[g]) << ',' << band.lower[g] << ',' << band.upper[g]
                     << '\n';
        }
      }
    }
  }
  return 0;
}

}  // namespace
}  // namespace caskdem

int main(int argc, char** argv) {
  try {
    return caskdem::run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
}
