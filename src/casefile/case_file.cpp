#include "casefile/case_file.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/error.h"
#include "core/text.h"
#include "model/build.h"

namespace caskdem {

namespace {

// A two-column table file (slip speed in m/s, friction coefficient): "#" comments and a
// header row allowed; comma, semicolon, tab or space separated.
std::vector<std::pair<double, double>> read_friction_table_file(const std::filesystem::path& file) {
  require_regular_file(file, "a friction table (slip speed in m/s, friction coefficient)");
  std::ifstream in(file);
  if (!in) throw InputError(located(file, 0, "cannot open the friction table"));
  std::vector<std::pair<double, double>> rows;
  std::string line;
  long number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    for (char& ch : line) {
      if (ch == ',' || ch == ';' || ch == '\t' || ch == '\r') ch = ' ';
    }
    const auto first = line.find_first_not_of(' ');
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    double speed = 0.0, coefficient = 0.0;
    std::string extra;
    const bool parsed = static_cast<bool>(fields >> speed >> coefficient) && !(fields >> extra);
    if (!parsed) {
      if (rows.empty() && std::isalpha(static_cast<unsigned char>(line[first]))) continue;  // header row
      throw InputError(located(file, number, "expected two numbers: slip speed (m/s) and friction coefficient"));
    }
    if (!std::isfinite(speed) || !std::isfinite(coefficient)) throw InputError(located(file, number, "expected finite numbers"));
    rows.emplace_back(speed, coefficient);
  }
  return rows;
}

double read_coefficient(TableReader& t, std::string_view key) {
  return t.in_range(key, t.quantity(key, Dimension::dimensionless), 0.0, 10.0);
}

// Keys that belong to other friction laws are an error, not silently ignored.
void reject_keys(TableReader& t, const std::string& law, std::initializer_list<std::string_view> keys) {
  for (std::string_view key : keys) {
    if (t.has(key)) t.fail(key, "does not apply to friction law \"" + law + "\"");
  }
}

void read_cask(TableReader& root, Case& c, bool three_d_allowed) {
  TableReader t = root.table("cask");
  c.cask.shape = t.choice("shape", {"cylinder", "polygon"});
  const long dimensions = t.optional_integer("dimensions").value_or(2);
  if (dimensions != 2 && dimensions != 3) t.fail("dimensions", "expected 2 (the planar model) or 3 (the cylinder in 3D)");
  c.cask.dimensions = static_cast<int>(dimensions);
  if (dimensions == 3 && !three_d_allowed) {
    t.fail("dimensions", "the 3D cask runs from case and ensemble files; measured specimens are planar");
  }
  if (dimensions == 3) {
    if (c.cask.shape != "cylinder") t.fail("dimensions", "the 3D cask is a cylinder: give shape = \"cylinder\"");
    // The 3D base is the whole circle (kernels/model3d.h): the planar footprint rules do not apply.
    for (const char* key : {"half_width", "footprint", "footprint_points"}) {
      if (t.has(key)) t.fail(key, "a 3D cask stands on its whole circular base; leave " + std::string(key) + " out");
    }
  }
  const double rounding = t.non_negative("rounding", t.quantity_or("rounding", Dimension::length, 0.005));
  const std::optional<double> mass = t.optional_quantity("mass", Dimension::mass);
  const std::optional<double> density = t.optional_quantity("density", Dimension::density);
  if (mass && density) t.fail("density", "give either mass or density, not both");
  if (!mass && !density) throw InputError(located(t.file(), root.line_of("cask"), "[cask] needs mass or density"));
  if (mass) t.positive("mass", *mass);
  if (density) t.positive("density", *density);
  const std::optional<double> inertia = t.optional_quantity("inertia", Dimension::moment_of_inertia);
  if (inertia) t.positive("inertia", *inertia);
  try {
    if (c.cask.shape == "cylinder") {
      Cylinder& cylinder = c.cask.cylinder;
      cylinder.diameter = t.positive("diameter", t.quantity("diameter", Dimension::length));
      cylinder.height = t.positive("height", t.quantity("height", Dimension::length));
      cylinder.mass = mass ? *mass : *density * std::numbers::pi / 4.0 * cylinder.diameter * cylinder.diameter * cylinder.height;
      cylinder.inertia = inertia;
      if (auto axial = t.optional_quantity("axial_inertia", Dimension::moment_of_inertia)) {
        if (dimensions != 3) t.fail("axial_inertia", "only a 3D cask ([cask] dimensions = 3) turns about its axis");
        cylinder.axial_inertia = t.positive("axial_inertia", *axial);
      }
      // Two corners at a half-width rule's b, or a distributed circular footprint (model/section.h).
      const bool distributed = t.choice("footprint", {"corners", "distributed"}, "corners") == "distributed";
      const std::string default_rule = distributed ? "radius" : "gyration";
      cylinder.rule = t.choice("half_width", {"gyration", "radius"}, default_rule) == "radius" ? HalfWidthRule::radius
                                                                                              : HalfWidthRule::gyration;
      if (distributed) {
        if (cylinder.rule != HalfWidthRule::radius) {
          t.fail("half_width", "a distributed footprint pivots on the rim: leave half_width out or give \"radius\"");
        }
        const long points = t.optional_integer("footprint_points").value_or(kDefaultFootprintPoints);
        if (points < kMinFootprintPoints || points > kMaxCorners) {
          t.fail("footprint_points", "expected " + std::to_string(kMinFootprintPoints) + " to " +
                                         std::to_string(kMaxCorners) + " contact points across the base");
        }
        cylinder.footprint_points = static_cast<int>(points);
      } else if (t.has("footprint_points")) {
        t.fail("footprint_points", "only a distributed footprint (footprint = \"distributed\") has contact points");
      }
      cylinder.eccentricity = t.quantity_or("eccentricity", Dimension::length, 0.0);
      c.model.section = cylinder_section(cylinder, rounding);
    } else {
      std::vector<Point> vertices;
      for (auto [x, y] : t.pairs("vertices")) vertices.push_back({x, y});
      const double depth = t.positive("depth", t.quantity("depth", Dimension::length));
      std::optional<Point> centre;
      if (auto p = t.optional_pair("centre_of_mass")) centre = Point{p->first, p->second};
      const double section_mass = mass ? *mass : *density * std::abs(polygon_area(vertices)) * depth;
      c.model.section = polygon_section(vertices, depth, section_mass, inertia, centre, rounding);
    }
  } catch (const std::invalid_argument& e) {
    throw InputError(located(t.file(), root.line_of("cask"), "[cask]: " + std::string(e.what())));
  }
  t.reject_unknown_keys();
}

void read_contact(TableReader& root, Case& c) {
  TableReader t = root.table("contact");
  const bool direct = t.has("normal_stiffness") || t.has("shear_stiffness");
  if (t.has_table("barkan")) {
    if (direct) t.fail("barkan", "give either normal_stiffness and shear_stiffness, or [contact.barkan], not both");
    TableReader b = t.table("barkan");
    BarkanFloor floor;
    floor.shear_modulus = b.positive("shear_modulus", b.quantity("shear_modulus", Dimension::stress));
    floor.poisson_ratio = b.in_range("poisson_ratio", b.quantity("poisson_ratio", Dimension::dimensionless), 0.0, 0.499);
    floor.beta_z = b.positive("beta_z", b.quantity_or("beta_z", Dimension::dimensionless, 2.1));
    floor.beta_x = b.positive("beta_x", b.quantity_or("beta_x", Dimension::dimensionless, 1.0));
    b.reject_unknown_keys();
    c.model.stiffness = barkan_stiffness(floor, c.model.section.base_area);
  } else {
    c.model.stiffness.normal = t.positive("normal_stiffness", t.quantity("normal_stiffness", Dimension::distributed_stiffness));
    c.model.stiffness.shear = t.positive("shear_stiffness", t.quantity("shear_stiffness", Dimension::distributed_stiffness));
  }
  c.model.normal_law = normal_law_of(t.choice("normal_law", normal_law_names(), normal_law_name(NormalLaw::linear)));
  c.parameters.impact_damping = t.non_negative("impact_damping", t.quantity_or("impact_damping", Dimension::slowness, 0.0));
  t.reject_unknown_keys();
}

void read_friction(TableReader& root, Case& c) {
  TableReader t = root.table("friction");
  const std::string law = t.choice("law", {"constant", "static_kinetic", "exponential", "table"});
  RealisationParameters& p = c.parameters;
  if (law == "constant") {
    reject_keys(t, law, {"static", "kinetic", "decay_speed", "table", "table_file"});
    c.model.friction_law = FrictionLaw::constant;
    p.friction_static = p.friction_kinetic = read_coefficient(t, "coefficient");
  } else if (law == "static_kinetic" || law == "exponential") {
    reject_keys(t, law, {"coefficient", "table", "table_file"});
    p.friction_static = read_coefficient(t, "static");
    p.friction_kinetic = read_coefficient(t, "kinetic");
    if (law == "exponential") {
      c.model.friction_law = FrictionLaw::exponential;
      p.friction_decay_speed = t.positive("decay_speed", t.quantity("decay_speed", Dimension::velocity));
    } else {
      reject_keys(t, law, {"decay_speed"});
      c.model.friction_law = FrictionLaw::static_kinetic;
    }
  } else {
    reject_keys(t, law, {"coefficient", "static", "kinetic", "decay_speed"});
    c.model.friction_law = FrictionLaw::tabulated;
    if (t.has("table") == t.has("table_file")) {
      throw InputError(located(t.file(), root.line_of("friction"), "[friction] law \"table\" needs exactly one of table or table_file"));
    }
    if (t.has("table")) {
      c.model.friction_table = t.pairs("table");
    } else {
      c.model.friction_table = read_friction_table_file(resolve_beside(t.file(), t.string("table_file")));
    }
    const auto& rows = c.model.friction_table;
    const std::string key = t.has("table") ? "table" : "table_file";
    if (rows.size() < 2 || rows.size() > static_cast<std::size_t>(kMaxFrictionTable)) {
      t.fail(key, "expected 2 to " + std::to_string(kMaxFrictionTable) + " rows of (slip speed, coefficient)");
    }
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (rows[i].second < 0.0) t.fail(key, "friction coefficients must be non-negative");
      if (i == 0 && rows[i].first != 0.0) t.fail(key, "the first row must be at slip speed 0");
      if (i > 0 && !(rows[i].first > rows[i - 1].first)) t.fail(key, "slip speeds must increase from row to row");
      if (i > 0 && !std::isfinite((rows[i].second - rows[i - 1].second) / (rows[i].first - rows[i - 1].first))) {
        t.fail(key, "rows " + std::to_string(i) + " and " + std::to_string(i + 1) +
                        " are too close in speed for their change of coefficient");
      }
    }
    p.friction_static = p.friction_kinetic = rows.front().second;
  }
  t.reject_unknown_keys();
}

void read_damping(TableReader& root, Case& c) {
  TableReader t = root.table("damping");
  c.parameters.damping_ratio = t.in_range("ratio", t.quantity("ratio", Dimension::dimensionless), 0.0, 10.0);
  if (auto f = t.optional_quantity("frequency", Dimension::frequency)) {
    c.parameters.damping_frequency = 2.0 * std::numbers::pi * t.positive("frequency", *f);
  }
  t.reject_unknown_keys();
}

// Longer than a day is a value in the wrong unit: no test or earthquake lasts that long, and the
// steps of such a run would overflow their count.
constexpr double kLongestDuration = 1e5;  // s
// A table acceleration above motion::kLargestGroundAcceleration (1000 m/s^2, about 100 g) is a
// value in the wrong unit: shaking tables and earthquakes stay within a few g.
// A synthetic record's sampling: at least 1e-5 s, and from ten samples to 1e8 (800 MB).
constexpr double kSmallestRecordStep = 1e-5;  // s
constexpr double kFewestRecordSamples = 10.0;
constexpr double kMostRecordSamples = 1e8;

// A duration that must be positive, at most kLongestDuration.
double positive_duration(const TableReader& t, std::string_view key, double value) {
  if (t.in_range(key, value, 0.0, kLongestDuration) == 0.0) t.fail(key, "expected a positive duration");
  return value;
}

void read_integration(TableReader& root, Case& c) {
  if (!root.has_table("integration")) return;
  TableReader t = root.table("integration");
  // The defaults are the caller's: a case's the paper's f_s = 0.01 and half-step slider (ModelSpec),
  // an ensemble's its own (ensemble/ensemble_file.h).
  c.model.safety_factor =
      t.in_range("safety_factor", t.quantity_or("safety_factor", Dimension::dimensionless, c.model.safety_factor), 1e-6, 1.0);
  c.model.contact_stiffness_scale = t.in_range(
      "contact_stiffness_scale", t.quantity_or("contact_stiffness_scale", Dimension::dimensionless, 1.0), 1e-4, 1.0);
  c.model.whole_step_terms =
      whole_step_terms_of(t.choice("slider", slider_names(), slider_name_of(c.model.whole_step_terms)));
  c.duration = t.in_range("duration", t.quantity_or("duration", Dimension::time, 0.0), 0.0, kLongestDuration);
  c.settle_time = t.in_range("settle_time", t.quantity_or("settle_time", Dimension::time, 2.0), 0.0, kLongestDuration);
  c.settle_time_given = t.has("settle_time");
  c.rest_cap = t.in_range("rest_cap", t.quantity_or("rest_cap", Dimension::time, 60.0), 0.0, kLongestDuration);
  c.rest_cap_given = t.has("rest_cap");
  if (c.rest_cap_given && c.cask.dimensions != 3) {
    t.fail("rest_cap", "a planar case runs for duration, or its motion and settle_time; rest_cap is a 3D case run's");
  }
  t.reject_unknown_keys();
}

void read_limits(TableReader& root, Case& c) {
  if (!root.has_table("limits")) return;
  TableReader t = root.table("limits");
  if (auto a = t.optional_quantity("tip_over_angle", Dimension::angle)) {
    c.model.tip_over_angle = t.in_range("tip_over_angle", *a, 1e-6, std::numbers::pi / 2.0);
  }
  if (auto h = t.optional_quantity("lift_off_height", Dimension::length)) c.model.lift_off_height = t.positive("lift_off_height", *h);
  if (auto w = t.optional_quantity("pad_half_width", Dimension::length)) c.model.pad_half_width = t.positive("pad_half_width", *w);
  t.reject_unknown_keys();
}

}  // namespace

MotionSpec read_motion(TableReader& t) { return read_motion(t, false); }

MotionSpec read_motion(TableReader& t, bool three_d) {
  MotionSpec m;
  if (!three_d) {
    for (const char* key : {"pair", "vertical_file", "incidence", "tails", "intensity"}) {
      if (t.has(key)) t.fail(key, "only a 3D cask ([cask] dimensions = 3) takes " + std::string(key));
    }
  } else {
    m.incidence = t.quantity_or("incidence", Dimension::angle, 0.0);
    if (!(std::abs(m.incidence) <= 2.0 * std::numbers::pi)) t.fail("incidence", "expected an angle of at most 360 degrees");
  }
  m.where = t.file().string() + ":" + std::to_string(t.line_of("kind"));
  const std::string kind = t.choice("kind", {"sine", "pulse", "record", "synthetic", "none"});
  if (kind == "none") {
    m.kind = MotionSpec::Kind::none;
  } else if (kind == "sine") {
    m.kind = MotionSpec::Kind::sine;
    m.amplitude = t.positive("amplitude", t.quantity("amplitude", Dimension::length));
    m.frequency = t.positive("frequency", t.quantity("frequency", Dimension::frequency));
    m.cycles = t.positive("cycles", t.quantity("cycles", Dimension::dimensionless));
    m.ramp_cycles = t.non_negative("ramp_cycles", t.quantity_or("ramp_cycles", Dimension::dimensionless, 2.0));
    if (2.0 * m.ramp_cycles > m.cycles) t.fail("ramp_cycles", "the ramps up and down must fit in the cycles");
    const double peak_acceleration = m.amplitude * std::pow(2.0 * std::numbers::pi * m.frequency, 2);
    if (!(peak_acceleration <= motion::kLargestGroundAcceleration))
      t.fail("frequency", "expected a sine whose peak acceleration A (2 pi f)^2 is at most " +
                              number_text(motion::kLargestGroundAcceleration) + " m/s^2 (about 100 g), got " +
                              number_text(peak_acceleration) + " m/s^2");
    if (m.cycles / m.frequency > kLongestDuration)
      t.fail("cycles", "expected at most " + number_text(kLongestDuration) + " s of shaking (cycles / frequency), got " +
                           number_text(m.cycles / m.frequency) + " s");
  } else if (kind == "pulse") {
    m.kind = MotionSpec::Kind::pulse;
    const std::string shape = t.choice("shape", {"half_sine", "one_sine", "rectangular"});
    m.shape = *motion::parse_pulse_shape(shape);
    m.pulse_amplitude = t.quantity("amplitude", Dimension::acceleration);
    if (m.pulse_amplitude == 0.0 || !(std::abs(m.pulse_amplitude) <= motion::kLargestGroundAcceleration))
      t.fail("amplitude", "expected a non-zero acceleration of at most " + number_text(motion::kLargestGroundAcceleration) +
                              " m/s^2 (about 100 g)");
    m.pulse_duration = positive_duration(t, "duration", t.quantity("duration", Dimension::time));
  } else if (kind == "synthetic") {
    m.kind = MotionSpec::Kind::synthetic;
    motion::SyntheticMotion& s = m.synthetic;
    const std::optional<long> seed = t.optional_integer("seed");
    if (seed && *seed < 0) t.fail("seed", "expected a non-negative whole number");
    s.seed = static_cast<std::uint64_t>(seed.value_or(1));
    s.duration = positive_duration(t, "duration", t.quantity_or("duration", Dimension::time, s.duration));
    s.time_step = t.in_range("time_step", t.quantity_or("time_step", Dimension::time, s.time_step), kSmallestRecordStep,
                             s.duration / kFewestRecordSamples);
    if (s.duration / s.time_step > kMostRecordSamples)
      t.fail("time_step", "expected at most " + number_text(kMostRecordSamples) + " samples (duration / time_step), got " +
                              number_text(s.duration / s.time_step));
    s.dominant_frequency = t.positive("dominant_frequency", t.quantity_or("dominant_frequency", Dimension::frequency, s.dominant_frequency));
    s.ground_damping = t.positive("ground_damping", t.quantity_or("ground_damping", Dimension::dimensionless, s.ground_damping));
    s.high_pass_frequency = t.positive("high_pass_frequency", t.quantity_or("high_pass_frequency", Dimension::frequency, s.high_pass_frequency));
    s.high_pass_damping = t.positive("high_pass_damping", t.quantity_or("high_pass_damping", Dimension::dimensionless, s.high_pass_damping));
    s.rise_time = t.positive("rise_time", t.quantity_or("rise_time", Dimension::time, s.rise_time));
    s.strong_duration = t.non_negative("strong_duration", t.quantity_or("strong_duration", Dimension::time, s.strong_duration));
    s.decay = t.positive("decay", t.quantity_or("decay", Dimension::frequency, s.decay));
    s.pga = t.positive("pga", t.quantity_or("pga", Dimension::acceleration, s.pga));
    if (!(s.pga <= motion::kLargestGroundAcceleration))
      t.fail("pga", "expected a PGA of at most " + std::string(motion::kLargestGroundAccelerationText) + ", got " +
                        number_text(s.pga) + " m/s^2");
    if (!(s.high_pass_frequency < s.dominant_frequency)) t.fail("high_pass_frequency", "expected a frequency below dominant_frequency");
  } else {
    m.kind = MotionSpec::Kind::record;
    m.file = resolve_beside(t.file(), t.string("file"));
    const std::string format = t.choice("format", {"automatic", "peer_nga_west2", "peer_old", "columns"}, "automatic");
    m.read.format = *motion::parse_record_format(format);
    if (auto unit = t.optional_string("unit")) {
      auto parsed = motion::parse_acceleration_unit(*unit);
      if (!parsed) t.fail("unit", "expected \"g\", \"gal\" or \"m/s^2\", got \"" + *unit + "\"");
      m.read.unit = parsed;
    }
    if (auto dt = t.optional_quantity("time_step", Dimension::time)) m.read.time_step = t.positive("time_step", *dt);
    if (three_d && t.has("pair")) {
      m.pair = resolve_beside(t.file(), t.string("pair"));
      if (t.has("vertical_file")) m.vertical_file = resolve_beside(t.file(), t.string("vertical_file"));
      m.tails = t.choice("tails", {"trim", "pad"}, "trim") == "pad" ? motion::TailRule::pad : motion::TailRule::trim;
      const std::string measure = t.choice("intensity", {"rotd50", "rotd100", "geometric_mean"}, "rotd50");
      m.pair_measure = measure == "rotd100"          ? MotionSpec::PairMeasure::rotd100
                       : measure == "geometric_mean" ? MotionSpec::PairMeasure::geometric_mean
                                                     : MotionSpec::PairMeasure::rotd50;
    } else if (three_d) {
      for (const char* key : {"vertical_file", "tails", "intensity"}) {
        if (t.has(key)) t.fail(key, "only a horizontal pair (pair = \"H2 file\") takes " + std::string(key));
      }
    }
    const int scalings = int(t.has("scale")) + int(t.has("target_pga")) + int(t.has("target_pgv"));
    if (scalings > 1) t.fail("scale", "give at most one of scale, target_pga and target_pgv");
    if (t.has("target_pga")) {
      m.scaling = MotionSpec::Scaling::target_pga;
      m.scale = t.positive("target_pga", t.quantity("target_pga", Dimension::acceleration));
    } else if (t.has("target_pgv")) {
      m.scaling = MotionSpec::Scaling::target_pgv;
      m.scale = t.positive("target_pgv", t.quantity("target_pgv", Dimension::velocity));
    } else {
      m.scaling = MotionSpec::Scaling::factor;
      m.scale = t.quantity_or("scale", Dimension::dimensionless, 1.0);
      if (m.scale == 0.0) t.fail("scale", "expected a non-zero factor (a negative one reverses the record)");
    }
    if (m.scaling == MotionSpec::Scaling::factor && !m.pair.empty() && t.has("intensity")) {
      t.fail("intensity", "the pair's measure is what target_pga or target_pgv sets; give one of them, or leave intensity out");
    }
  }
  if (three_d && m.kind != MotionSpec::Kind::record) {
    for (const char* key : {"pair", "vertical_file", "tails", "intensity"}) {
      if (t.has(key)) t.fail(key, "only a recorded motion (kind = \"record\") takes " + std::string(key));
    }
  }
  m.similarity_scale = t.positive("similarity_scale", t.quantity_or("similarity_scale", Dimension::dimensionless, 1.0));
  return m;
}

std::unique_ptr<motion::TableMotion> make_motion(const MotionSpec& spec, double* applied_scale) {
  const double time_factor = 1.0 / std::sqrt(spec.similarity_scale);
  if (applied_scale) *applied_scale = 1.0;
  switch (spec.kind) {
    case MotionSpec::Kind::none:
      return motion::make_still();
    case MotionSpec::Kind::sine:
      // Similarity: lengths 1/N, time 1/sqrt(N) (frequency sqrt(N)), acceleration unchanged.
      return motion::make_sine(spec.amplitude / spec.similarity_scale, spec.frequency / time_factor, spec.cycles,
                               spec.ramp_cycles);
    case MotionSpec::Kind::pulse:
      return motion::make_pulse(spec.shape, spec.pulse_amplitude, spec.pulse_duration * time_factor);
    case MotionSpec::Kind::synthetic:
    case MotionSpec::Kind::record: {
      motion::Record record = spec.kind == MotionSpec::Kind::synthetic ? motion::synthetic_record(spec.synthetic)
                                                                         : motion::read_record(spec.file, spec.read);
      const char* key = spec.scaling == MotionSpec::Scaling::target_pga   ? "target_pga"
                        : spec.scaling == MotionSpec::Scaling::target_pgv ? "target_pgv"
                                                                          : "scale";
      // Every scaling multiplies the record by one factor: the ratio of its peaks after and before.
      const auto peak = [](const motion::Record& r) {
        double p = 0.0;
        for (double a : r.acceleration) p = std::max(p, std::abs(a));
        return p;
      };
      const double peak_before = peak(record);
      try {
        if (spec.scaling == MotionSpec::Scaling::target_pga) record = motion::scaled_to_pga(record, spec.scale);
        else if (spec.scaling == MotionSpec::Scaling::target_pgv) record = motion::scaled_to_pgv(record, spec.scale);
        else record = motion::scaled(record, spec.scale);
        if (applied_scale && peak_before > 0.0) *applied_scale = peak(record) / peak_before;
        // PGV targets refer to the prototype motion; the time compression follows.
        key = "similarity_scale";
        if (spec.similarity_scale != 1.0) record = motion::time_scaled(record, time_factor);
      } catch (const std::invalid_argument& e) {
        throw InputError(located(spec.file, 0, std::string(e.what()) + " (asked for by " + key +
                                                    (spec.where.empty() ? "" : " of the motion at " + spec.where) + ")"));
      }
      return motion::make_record_motion(std::move(record));
    }
  }
  return motion::make_still();
}

void read_cask_and_contact(TableReader& root, Case& c, bool three_d_allowed) {
  read_cask(root, c, three_d_allowed);
  const RealisationParameters mass_properties = nominal_parameters(c.model);
  c.parameters.mass = mass_properties.mass;
  c.parameters.inertia = mass_properties.inertia;
  c.parameters.centre_of_mass = mass_properties.centre_of_mass;
  read_contact(root, c);
  read_friction(root, c);
  read_damping(root, c);
  read_integration(root, c);
  read_limits(root, c);
}

const std::vector<std::string>& motion_keys() {
  static const std::vector<std::string> keys = {
      "kind",
      // sine
      "amplitude", "frequency", "cycles", "ramp_cycles",
      // pulse (amplitude, duration)
      "shape",
      // synthetic
      "seed", "duration", "time_step", "dominant_frequency", "ground_damping", "high_pass_frequency",
      "high_pass_damping", "rise_time", "strong_duration", "decay", "pga",
      // record (time_step)
      "file", "format", "unit", "scale", "target_pga", "target_pgv",
      // a 3D cask's horizontal pair (record) and direction (any)
      "pair", "vertical_file", "tails", "intensity", "incidence",
      // any
      "similarity_scale"};
  return keys;
}

const KeySchema& shared_case_keys() {
  static const KeySchema schema = {
      {"cask",
       {"shape", "dimensions", "rounding", "mass", "density", "inertia", "diameter", "height", "half_width",
        "footprint", "footprint_points", "eccentricity", "axial_inertia", "vertices", "depth", "centre_of_mass"}},
      {"contact", {"normal_stiffness", "shear_stiffness", "barkan", "normal_law", "impact_damping"}},
      {"contact.barkan", {"shear_modulus", "poisson_ratio", "beta_z", "beta_x"}},
      {"friction", {"law", "coefficient", "static", "kinetic", "decay_speed", "table", "table_file"}},
      {"damping", {"ratio", "frequency"}},
      {"integration", {"safety_factor", "contact_stiffness_scale", "slider", "duration", "settle_time", "rest_cap"}},
      {"limits", {"tip_over_angle", "lift_off_height", "pad_half_width"}},
  };
  return schema;
}

const KeySchema& case_file_keys() {
  static const KeySchema schema = [] {
    KeySchema s = {
        {"", {"title", "cask", "contact", "friction", "damping", "integration", "limits", "motion", "free_vibration",
              "output"}},
    };
    for (const KeyTable& t : shared_case_keys()) s.push_back(t);
    KeyTable motion{"motion", motion_keys()};
    motion.keys.push_back("vertical");
    s.push_back(motion);
    s.push_back({"motion.vertical", motion_keys()});
    s.push_back({"free_vibration", {"initial_tilt_ratio", "duration", "ratios", "target_restitution"}});
    s.push_back({"output", {"directory", "interval", "csv", "hdf5", "plot"}});
    return s;
  }();
  return schema;
}

void require_planar(const Case& c, const std::string& command) {
  if (c.cask.dimensions == 3) {
    throw InputError(located(c.file, 0, "`" + command + "` runs the planar model, and this cask is 3D ([cask] dimensions = 3)"));
  }
}

Case load_case(const std::filesystem::path& file) { return read_case(parse_toml_file(file), file); }

Case read_case(const toml::table& document, const std::filesystem::path& file) {
  TableReader root(document, file, "", 0, &case_file_keys());
  Case c;
  c.file = file;
  c.name = file.stem().string();
  c.title = root.optional_string("title").value_or(c.name);
  read_cask_and_contact(root, c, true);
  if (root.has_table("motion")) {
    TableReader t = root.table("motion");
    c.horizontal = read_motion(t, c.cask.dimensions == 3);
    if (t.has_table("vertical")) {
      TableReader v = t.table("vertical");
      if (!c.horizontal.vertical_file.empty()) {
        t.fail("vertical_file", "give the vertical either as vertical_file of the set or as [motion.vertical], not both");
      }
      for (const char* key : {"pair", "vertical_file", "tails", "intensity", "incidence"}) {
        if (v.has(key)) v.fail(key, "the vertical component has no pair or direction; give " + std::string(key) + " in [motion]");
      }
      c.vertical = read_motion(v);
      v.reject_unknown_keys();
    }
    t.reject_unknown_keys();
  } else {
    root.accept("motion");
  }
  if (root.has_table("free_vibration")) {
    TableReader t = root.table("free_vibration");
    FreeVibrationSpec& f = c.free_vibration;
    f.initial_tilt_ratio = t.in_range("initial_tilt_ratio", t.quantity_or("initial_tilt_ratio", Dimension::dimensionless, 0.5), 0.01, 0.99);
    f.duration = t.in_range("duration", t.quantity_or("duration", Dimension::time, 0.0), 0.0, kLongestDuration);
    f.ratios = static_cast<int>(t.optional_integer("ratios").value_or(3));
    if (f.ratios < 1 || f.ratios > kPeakCount - 1) t.fail("ratios", "expected 1 to " + std::to_string(kPeakCount - 1));
    if (auto target = t.optional_quantity("target_restitution", Dimension::dimensionless)) {
      f.target_restitution = t.in_range("target_restitution", *target, 0.01, 0.9999);
    }
    t.reject_unknown_keys();
  }
  c.output.directory = std::filesystem::path("results") / c.name;
  if (root.has_table("output")) {
    TableReader t = root.table("output");
    if (auto d = t.optional_string("directory")) c.output.directory = *d;
    c.output.interval = t.positive("interval", t.quantity_or("interval", Dimension::time, 1e-3));
    c.output.csv = t.boolean_or("csv", true);
    c.output.hdf5 = t.boolean_or("hdf5", true);
    c.output.plot = t.boolean_or("plot", true);
    t.reject_unknown_keys();
  }
  root.reject_unknown_keys();
  return c;
}

}  // namespace caskdem
