#include "ensemble/ensemble_file.h"

#include "motion/response_spectrum.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "core/error.h"
#include "core/text.h"
#include "core/units.h"

namespace caskdem {

namespace {

Dimension dimension_of(const std::string& parameter) {
  if (parameter == "friction_decay_speed") return Dimension::velocity;
  if (parameter == "mass") return Dimension::mass;
  if (parameter == "centre_height") return Dimension::length;
  if (parameter == "incidence") return Dimension::angle;
  return Dimension::dimensionless;
}

// A lognormal spread wider than a factor e^3 = 20 per standard deviation is not a parameter's
// uncertainty (and its far draws overflow).
constexpr double kLargestLogStd = 3.0;
// Truncation bounds that hold less of the distribution than this leave it degenerate.
constexpr double kSmallestTruncationMass = 1e-6;
// The results of one run are held in memory: 1e8 realisations take about 16 GB.
constexpr long kMostRealisations = 100'000'000;

Distribution read_distribution(TableReader& t, const std::string& parameter) {
  const Dimension dimension = dimension_of(parameter);
  Distribution d;
  const std::string kind = t.choice("distribution", {"constant", "uniform", "normal", "lognormal"});
  auto finite = [&](const char* key) {
    const double v = t.quantity(key, dimension);
    if (!std::isfinite(v)) t.fail(key, "expected a finite number");
    return v;
  };
  if (kind == "constant") {
    d.kind = Distribution::Kind::constant;
    d.first = finite("value");
  } else if (kind == "uniform") {
    d.kind = Distribution::Kind::uniform;
    d.first = finite("low");
    d.second = finite("high");
    if (!(d.second > d.first)) t.fail("high", "expected high > low");
  } else if (kind == "normal") {
    d.kind = Distribution::Kind::normal;
    d.first = finite("mean");
    d.second = t.positive("std", finite("std"));
  } else {
    d.kind = Distribution::Kind::lognormal;
    d.first = t.positive("median", finite("median"));
    d.second = t.in_range("log_std", t.quantity("log_std", Dimension::dimensionless), 0.0, kLargestLogStd);
    if (d.second == 0.0) t.fail("log_std", "expected a positive value (a constant is distribution = \"constant\")");
  }
  if (kind == "normal" || kind == "lognormal") {
    if (auto low = t.optional_quantity("low", dimension)) d.low = *low;
    if (auto high = t.optional_quantity("high", dimension)) d.high = *high;
    if (!(d.high > d.low)) t.fail("high", "expected high > low");
    // Bounds far out in a tail would put every sample on a bound.
    if (d.truncation_mass() < kSmallestTruncationMass)
      t.fail("low", "the bounds [low, high] hold a probability of " + number_text(d.truncation_mass()) +
                        " of the distribution; expected bounds around its centre");
  }
  // Physical ranges: coefficients and masses cannot be negative; restitution lies in (0, 1).
  const double lowest = d.lowest(), highest = d.highest();
  const std::string key = kind == "constant" ? "value" : (kind == "uniform" ? "low" : "low");
  if (parameter == "restitution") {
    if (!(lowest > 0.0 && highest < 1.0)) {
      t.fail(key, "a restitution must lie in (0, 1): bound the distribution with low and high inside it");
    }
  } else if (parameter == "mass" || parameter == "centre_height" || parameter == "friction_decay_speed") {
    // A lognormal is positive everywhere; the others need a positive lower bound.
    if (d.kind != Distribution::Kind::lognormal && !(lowest > 0.0)) {
      t.fail(key, "expected a positive lower bound (give low for a normal distribution)");
    }
  } else if (parameter == "incidence") {
    // Any direction: a cylinder's response repeats every 180 degrees of a pair turned.
    if (!(lowest >= -2.0 * std::numbers::pi && highest <= 2.0 * std::numbers::pi))
      t.fail(key, "expected incidence angles within [-360, 360] degrees (bound a normal distribution with low and high)");
  } else if (!(lowest >= 0.0)) {
    t.fail(key, "a friction coefficient cannot be negative (give low = 0 or more for a normal distribution)");
  }
  t.reject_unknown_keys();
  return d;
}

}  // namespace

std::string intensity_name(IntensityMeasure measure) {
  switch (measure) {
    case IntensityMeasure::pga: return "pga";
    case IntensityMeasure::pgv: return "pgv";
    case IntensityMeasure::pga_ratio: return "pga_ratio";
    case IntensityMeasure::pgv_ratio: return "pgv_ratio";
    case IntensityMeasure::sa: return "sa";
  }
  return "pga";
}

std::string intensity_display_unit(IntensityMeasure measure) {
  switch (measure) {
    case IntensityMeasure::pga:
    case IntensityMeasure::sa: return "g";
    case IntensityMeasure::pgv: return "cm/s";
    case IntensityMeasure::pga_ratio:
    case IntensityMeasure::pgv_ratio: return "";
  }
  return "";
}

double intensity_display_unit_to_si(IntensityMeasure measure) {
  switch (measure) {
    case IntensityMeasure::pga:
    case IntensityMeasure::sa: return units::standard_gravity;
    case IntensityMeasure::pgv: return 0.01;
    case IntensityMeasure::pga_ratio:
    case IntensityMeasure::pgv_ratio: return 1.0;
  }
  return 1.0;
}

std::string intensity_text(IntensityMeasure measure, double value) {
  std::ostringstream out;
  out << std::setprecision(4);
  switch (measure) {
    case IntensityMeasure::pga:
    case IntensityMeasure::sa: out << units::si_to_g(value) << " g"; break;
    case IntensityMeasure::pgv: out << units::m_to_cm(value) << " cm/s"; break;
    case IntensityMeasure::pga_ratio:
    case IntensityMeasure::pgv_ratio: out << value; break;
  }
  return out.str();
}

const KeySchema& ensemble_file_keys() {
  static const KeySchema schema = [] {
    KeySchema s = {
        {"", {"title", "cask", "contact", "friction", "damping", "integration", "limits", "free_vibration", "motions",
              "uncertain", "intensity", "sampling", "limit_states", "fragility", "run"}},
    };
    for (const KeyTable& t : shared_case_keys()) s.push_back(t);
    s.push_back({"free_vibration", {"initial_tilt_ratio", "ratios"}});
    KeyTable motions{"motions", motion_keys()};
    motions.keys.push_back("name");
    s.push_back(motions);
    s.push_back({"uncertain", uncertain_parameter_names()});
    s.push_back({"uncertain.*", {"distribution", "kind", "value", "low", "high", "mean", "std", "median", "log_std"}});
    s.push_back({"intensity", {"measure", "period", "damping_ratio", "levels", "realisations", "pair_measure"}});
    s.push_back({"sampling", {"method", "seed", "epistemic_points"}});
    s.push_back({"limit_states", {"tip_over", "rotation_ratio", "sliding"}});
    s.push_back({"fragility", {"bootstrap", "confidence"}});
    s.push_back({"run", {"block_lanes", "checkpoint_interval", "device"}});
    return s;
  }();
  return schema;
}

EnsembleSpec load_ensemble(const std::filesystem::path& file) {
  const toml::table document = parse_toml_file(file);
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return read_ensemble(document, file, text.str());
}

EnsembleSpec read_ensemble(const toml::table& document, const std::filesystem::path& file, const std::string& text) {
  TableReader root(document, file, "", 0, &ensemble_file_keys());
  EnsembleSpec e;
  e.file = file;
  e.name = file.stem().string();
  e.toml_text = text;
  e.title = root.optional_string("title").value_or(e.name);

  Case& c = e.base;
  c.file = file;
  c.name = e.name;
  c.title = e.title;
  c.model.safety_factor = kEnsembleSafetyFactor;
  c.model.whole_step_terms = kEnsembleSlider;
  read_cask_and_contact(root, c, /*three_d_allowed=*/true);
  if (c.rest_cap_given) {
    root.table("integration").fail("rest_cap", "an ensemble's realisations run for duration, or their motion and "
                                               "settle_time; rest_cap is a 3D case run's");
  }
  if (root.has_table("free_vibration")) {
    TableReader t = root.table("free_vibration");
    c.free_vibration.initial_tilt_ratio =
        t.in_range("initial_tilt_ratio", t.quantity_or("initial_tilt_ratio", Dimension::dimensionless, 0.5), 0.01, 0.99);
    c.free_vibration.ratios = static_cast<int>(t.optional_integer("ratios").value_or(3));
    if (c.free_vibration.ratios < 1 || c.free_vibration.ratios > kPeakCount - 1) t.fail("ratios", "expected 1 to 7");
    t.reject_unknown_keys();
  }

  // Motions: an array of tables, each like a case's [motion].
  const toml::node* motions = document.get("motions");
  const toml::array* list = motions ? motions->as_array() : nullptr;
  if (!list || list->empty()) {
    throw InputError(located(file, motions ? static_cast<long>(motions->source().begin.line) : 0,
                             "key motions: expected one or more [[motions]] tables"));
  }
  root.accept("motions");
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::table* table = (*list)[i].as_table();
    if (!table) throw InputError(located(file, static_cast<long>((*list)[i].source().begin.line), "key motions: expected tables"));
    TableReader t(*table, file, "motions[" + std::to_string(i) + "]", static_cast<long>(table->source().begin.line),
                  root.schema());
    std::string label = t.optional_string("name").value_or("");
    // [intensity] scales every motion to each level, so a factor or target of its own would
    // be silently undone.
    for (const char* key : {"scale", "target_pga", "target_pgv"}) {
      if (t.has(key)) {
        t.fail(key, "an ensemble scales each motion to the [intensity] levels; expected no scale, target_pga or "
                    "target_pgv in [[motions]]");
      }
    }
    // A realisation's direction is sampled ([uncertain] incidence), and one measure scales every
    // pair ([intensity] pair_measure).
    if (t.has("incidence")) t.fail("incidence", "an ensemble samples the incidence: give [uncertain] incidence instead");
    if (t.has("intensity")) t.fail("intensity", "an ensemble scales every pair by one measure: give [intensity] pair_measure instead");
    MotionSpec m = read_motion(t, e.three_d());
    if (m.kind == MotionSpec::Kind::none) t.fail("kind", "an ensemble motion must move the table");
    if (label.empty()) {
      label = m.kind == MotionSpec::Kind::record ? m.file.stem().string() : "motion " + std::to_string(i + 1);
    }
    t.reject_unknown_keys();
    e.motions.push_back(m);
    e.motion_names.push_back(label);
  }

  if (root.has_table("uncertain")) {
    TableReader t = root.table("uncertain");
    for (const std::string& name : uncertain_parameter_names()) {
      t.accept(name);
      if (!t.has(name)) continue;
      if (!t.has_table(name)) t.fail(name, "expected a table { distribution = \"...\", ... }");
      TableReader p = t.table(name);
      if (p.choice("kind", {"aleatory", "epistemic"}, "aleatory") == "epistemic") e.epistemic.insert(name);
      e.uncertain[name] = read_distribution(p, name);
    }
    t.reject_unknown_keys();
    const FrictionLaw law = c.model.friction_law;
    if (e.uncertain.count("friction_kinetic") && law != FrictionLaw::static_kinetic && law != FrictionLaw::exponential) {
      t.fail("friction_kinetic", "the friction law has no kinetic coefficient (use static_kinetic or exponential)");
    }
    if (e.uncertain.count("friction_decay_speed") && law != FrictionLaw::exponential) {
      t.fail("friction_decay_speed", "only the exponential friction law has a decay speed");
    }
    if (auto centre = e.uncertain.find("centre_height"); centre != e.uncertain.end()) {
      double top = 0.0;
      for (const Point& p : c.model.section.outline) top = std::max(top, p.y);
      if (!(centre->second.lowest() > 0.0 && centre->second.highest() < top))
        t.fail("centre_height", "the centre of mass must lie inside the cask, 0 to " + number_text(top) +
                                    " m above its base; the distribution spans " +
                                    number_text(centre->second.lowest()) + " to " +
                                    number_text(centre->second.highest()) + " m (bound it with low and high)");
    }
    if (e.uncertain.count("friction_static") && law == FrictionLaw::tabulated) {
      t.fail("friction_static", "a tabulated friction law cannot vary its coefficient");
    }
    if (e.uncertain.count("incidence") && !e.three_d()) {
      t.fail("incidence", "only a 3D cask ([cask] dimensions = 3) has an incidence: the planar model has one direction");
    }
    if (e.three_d() && e.uncertain.count("restitution")) {
      t.fail("restitution", "the 3D cask's damping is the [damping] ratio: its restitution is not calibrated per realisation");
    }
  }
  // The horizontal pair comes from any direction unless the ensemble says otherwise.
  if (e.three_d() && !e.uncertain.count("incidence")) {
    Distribution any_direction;
    any_direction.kind = Distribution::Kind::uniform;
    any_direction.first = 0.0;
    any_direction.second = std::numbers::pi;
    e.uncertain["incidence"] = any_direction;
  }

  {
    TableReader t = root.table("intensity");
    const std::string measure = t.choice("measure", {"pga", "pgv", "pga_ratio", "pgv_ratio", "sa"});
    e.measure = measure == "pga" ? IntensityMeasure::pga
                : measure == "pgv" ? IntensityMeasure::pgv
                : measure == "pga_ratio" ? IntensityMeasure::pga_ratio
                : measure == "sa" ? IntensityMeasure::sa
                                         : IntensityMeasure::pgv_ratio;
    if (e.measure == IntensityMeasure::sa) {
      e.spectral_period = t.quantity("period", Dimension::time);
      if (!(e.spectral_period >= motion::kShortestSpectralPeriod && e.spectral_period <= motion::kLongestSpectralPeriod))
        t.fail("period", "expected a period from " + number_text(motion::kShortestSpectralPeriod) + " to " +
                             number_text(motion::kLongestSpectralPeriod) + " s");
      if (auto zeta = t.optional_quantity("damping_ratio", Dimension::dimensionless)) {
        if (!(*zeta >= 0.0 && *zeta < 1.0)) t.fail("damping_ratio", "expected a damping ratio from 0 to below 1 (0.05 is 5 %)");
        e.spectral_damping_ratio = *zeta;
      }
    } else if (t.has("period") || t.has("damping_ratio")) {
      t.fail(t.has("period") ? "period" : "damping_ratio", "only measure = \"sa\" has a period and a damping ratio");
    }
    if (e.three_d()) {
      if (e.measure == IntensityMeasure::sa) t.fail("measure", "a 3D ensemble is scaled by its pairs' PGA or PGV (pga, pgv, pga_ratio or pgv_ratio)");
      const std::string pair = t.choice("pair_measure", {"rotd50", "rotd100", "geometric_mean"}, "rotd50");
      e.pair_measure = pair == "rotd100"          ? MotionSpec::PairMeasure::rotd100
                       : pair == "geometric_mean" ? MotionSpec::PairMeasure::geometric_mean
                                                  : MotionSpec::PairMeasure::rotd50;
    } else if (t.has("pair_measure")) {
      t.fail("pair_measure", "only a 3D cask ([cask] dimensions = 3) has horizontal pairs to measure");
    }
    const Dimension dimension = e.measure == IntensityMeasure::pga || e.measure == IntensityMeasure::sa ? Dimension::acceleration
                                : e.measure == IntensityMeasure::pgv ? Dimension::velocity
                                                                     : Dimension::dimensionless;
    const toml::node* levels = t.has("levels") ? document["intensity"]["levels"].node() : nullptr;
    const toml::array* values = levels ? levels->as_array() : nullptr;
    t.accept("levels");
    if (!values || values->empty()) t.fail("levels", "expected a non-empty list of intensity levels (stripes)");
    for (const toml::node& v : *values) {
      std::string error;
      std::optional<double> level;
      if (auto number = v.value<double>(); number && (v.is_floating_point() || v.is_integer())) level = *number;
      if (auto text = v.value<std::string>()) level = parse_quantity(*text, dimension, error);
      if (!level || !std::isfinite(*level) || !(*level > 0.0)) {
        throw InputError(located(file, static_cast<long>(v.source().begin.line),
                                 "key intensity.levels: expected positive " + dimension_name(dimension) + " values" +
                                     (error.empty() ? "" : " (" + error + ")")));
      }
      if (!e.levels.empty() && !(*level > e.levels.back())) t.fail("levels", "expected increasing levels");
      e.levels.push_back(*level);
    }
    const long count = t.integer("realisations");
    if (count < 1 || count > kMostRealisations)
      t.fail("realisations", "expected at least 1 and at most " + std::to_string(kMostRealisations) + " realisations per stripe");
    if (static_cast<double>(count) * static_cast<double>(e.levels.size()) > double(kMostRealisations))
      t.fail("realisations", "expected at most " + std::to_string(kMostRealisations) + " realisations in all (" +
                                 std::to_string(e.levels.size()) + " stripes of " + std::to_string(count) + ")");
    e.realisations_per_stripe = count;
    t.reject_unknown_keys();
  }

  if (root.has_table("sampling")) {
    TableReader t = root.table("sampling");
    e.sampling = t.choice("method", {"latin_hypercube", "monte_carlo"}, "latin_hypercube") == "monte_carlo"
                     ? SamplingMethod::monte_carlo
                     : SamplingMethod::latin_hypercube;
    const long seed = t.optional_integer("seed").value_or(1);
    if (seed < 0) t.fail("seed", "expected a non-negative whole number");
    e.seed = static_cast<std::uint64_t>(seed);
    if (auto points = t.optional_integer("epistemic_points")) {
      if (e.epistemic.empty()) t.fail("epistemic_points", "no [uncertain] parameter has kind = \"epistemic\"");
      if (*points < 3 || *points > 10000) t.fail("epistemic_points", "expected 3 to 10000 outer points");
      e.epistemic_points = static_cast<int>(*points);
    }
    t.reject_unknown_keys();
  }
  if (static_cast<double>(e.realisation_count()) > double(kMostRealisations))
    throw InputError(located(file, 0, "key sampling.epistemic_points: expected at most " +
                                          std::to_string(kMostRealisations) + " realisations in all (" +
                                          std::to_string(e.outer_count()) + " outer points of " +
                                          std::to_string(e.realisations_per_outer_point()) + ")"));

  {
    TableReader t = root.table("limit_states");
    if (t.boolean_or("tip_over", true)) e.limit_states.push_back({LimitState::Kind::tip_over, 0.0, "tip_over"});
    const toml::node* ratios = document["limit_states"]["rotation_ratio"].node();
    t.accept("rotation_ratio");
    if (ratios) {
      const toml::array* list_of = ratios->as_array();
      if (!list_of) t.fail("rotation_ratio", "expected a list of max |theta| / alpha thresholds");
      for (const toml::node& v : *list_of) {
        auto r = v.value<double>();
        if (!r || !(*r > 0.0)) t.fail("rotation_ratio", "expected positive thresholds");
        e.limit_states.push_back({LimitState::Kind::rotation_ratio, *r, "rotation_ratio_" + number_text(*r)});
      }
    }
    const toml::node* slides = document["limit_states"]["sliding"].node();
    t.accept("sliding");
    if (slides) {
      const toml::array* list_of = slides->as_array();
      if (!list_of) t.fail("sliding", "expected a list of sliding distances such as [\"5 cm\"]");
      for (const toml::node& v : *list_of) {
        std::string error;
        std::optional<double> d;
        if (auto number = v.value<double>(); number && (v.is_floating_point() || v.is_integer())) d = *number;
        if (auto text = v.value<std::string>()) d = parse_quantity(*text, Dimension::length, error);
        if (!d || !(*d > 0.0)) t.fail("sliding", "expected positive distances" + (error.empty() ? "" : " (" + error + ")"));
        e.limit_states.push_back({LimitState::Kind::sliding, *d, "sliding_" + number_text(*d) + "m"});
      }
    }
    if (e.limit_states.empty()) t.fail("tip_over", "expected at least one limit state");
    // Each limit state is a group of the result file, named by its threshold (6 digits):
    // two alike would collide only when the finished run is written.
    for (std::size_t i = 0; i < e.limit_states.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        if (e.limit_states[i].name != e.limit_states[j].name) continue;
        t.fail(e.limit_states[i].kind == LimitState::Kind::sliding ? "sliding" : "rotation_ratio",
               "the threshold " + e.limit_states[i].name + " is given twice; expected distinct thresholds");
      }
    }
    t.reject_unknown_keys();
  }

  if (root.has_table("fragility")) {
    TableReader t = root.table("fragility");
    const long replicates = t.optional_integer("bootstrap").value_or(200);
    if (replicates < 0 || replicates > 100000) t.fail("bootstrap", "expected 0 to 100000 replicates");
    e.bootstrap_replicates = static_cast<int>(replicates);
    e.confidence = t.in_range("confidence", t.quantity_or("confidence", Dimension::dimensionless, 0.95), 0.5, 0.999);
    t.reject_unknown_keys();
  }
  if (root.has_table("run")) {
    TableReader t = root.table("run");
    const long lanes = t.optional_integer("block_lanes").value_or(64);
    if (lanes < 1 || lanes > 4096) t.fail("block_lanes", "expected 1 to 4096");
    e.block_lanes = static_cast<int>(lanes);
    e.checkpoint_interval = t.positive("checkpoint_interval", t.quantity_or("checkpoint_interval", Dimension::time, 10.0));
    e.device = t.choice("device", {"auto", "cpu", "cuda"}, "auto");
    e.device_line = t.has("device") ? t.line_of("device") : 0;
    t.reject_unknown_keys();
  }
  if (root.has("motion")) root.fail("motion", "an ensemble lists its motions as [[motions]] tables");
  root.reject_unknown_keys();
  return e;
}

}  // namespace caskdem
