#include "diagnosis/measured_set.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include "core/error.h"
#include "core/text.h"
#include "diagnosis/mechanisms.h"

namespace caskdem::diagnosis {

namespace {

// An optional whole number of the [diagnosis] table within [low, high] (`what` names its unit);
// `fallback` when the key is absent.
int whole_number_in(TableReader& t, std::string_view key, int fallback, int low, int high, const std::string& what) {
  const long value = t.optional_integer(key).value_or(fallback);
  if (value < low || value > high) {
    t.fail(key, "expected " + number_text(low) + " to " + number_text(high) + " " + what);
  }
  return static_cast<int>(value);
}

// The specimen from its parsed document (`specimen` names it in errors).
Case specimen_from(const toml::table& document, const std::filesystem::path& specimen, DiagnosisSettings* settings) {
  TableReader root(document, specimen, "");
  Case c;
  c.file = specimen;
  c.name = specimen.parent_path().filename().string();
  c.title = root.optional_string("title").value_or(c.name);
  read_cask_and_contact(root, c);
  // Each test lasts as long as its CSV: a duration here would be silently unused.
  if (root.has_table("integration")) {
    TableReader t = root.table("integration");
    for (const char* key : {"duration", "settle_time"}) {
      if (t.has(key)) t.fail(key, "not used by a measured-data directory (each test lasts as long as its CSV); expected "
                                  "only safety_factor in [integration]");
    }
  }
  if (c.model.friction_law != FrictionLaw::constant) {
    root.fail("friction", "the diagnosis starts from constant friction (law = \"constant\"); velocity-dependent "
                          "friction is one of the mechanisms it tests");
  }
  DiagnosisSettings local;
  DiagnosisSettings& s = settings ? *settings : local;
  if (root.has_table("diagnosis")) {
    TableReader t = root.table("diagnosis");
    if (t.has("heldout")) {
      const toml::array* list = document["diagnosis"]["heldout"].as_array();
      t.accept("heldout");
      if (!list || list->empty())
        t.fail("heldout", "expected a list of test names such as [\"test5\", \"test6\"] (leave the key out for the "
                          "default, every third test from the second)");
      for (const toml::node& n : *list) {
        auto name = n.value<std::string>();
        if (!name) t.fail("heldout", "expected test names in quotes");
        if (std::find(s.heldout.begin(), s.heldout.end(), *name) != s.heldout.end())
          t.fail("heldout", "the test \"" + *name + "\" is named twice; expected each test once");
        s.heldout.push_back(*name);
      }
    }
    const DiagnosisSettings defaults;
    s.starts = whole_number_in(t, "starts", defaults.starts, 1, 64, "searches");
    s.evaluations = whole_number_in(t, "evaluations", defaults.evaluations, 10, 5000, "evaluations");
    s.exploration = whole_number_in(t, "exploration", defaults.exploration, 16, 100000, "points");
    const long seed = t.optional_integer("seed").value_or(static_cast<long>(defaults.seed));
    if (seed < 0) t.fail("seed", "expected a non-negative whole number");
    s.seed = static_cast<std::uint64_t>(seed);
    s.input_realisations =
        whole_number_in(t, "input_realisations", defaults.input_realisations, 1, 64, "table inputs per test");
    t.reject_unknown_keys();
  }
  if (root.has_table("table")) {
    TableReader t = root.table("table");
    TableLimits limits;
    limits.peak_acceleration =
        t.positive("peak_acceleration", t.quantity("peak_acceleration", Dimension::acceleration));
    limits.peak_velocity = t.positive("peak_velocity", t.quantity("peak_velocity", Dimension::velocity));
    limits.stroke = t.positive("stroke", t.quantity("stroke", Dimension::length));
    const toml::array* range = document["table"]["frequencies"].as_array();
    t.accept("frequencies");
    const std::string expected =
        "expected two frequencies, the table's lowest and highest, such as [\"0.5 Hz\", "
        "\"20 Hz\"]";
    if (!range || range->size() != 2) t.fail("frequencies", expected);
    double bounds[2];
    for (int i = 0; i < 2; ++i) {
      const toml::node& n = *range->get(static_cast<std::size_t>(i));
      std::string error;
      std::optional<double> value;
      if (auto text = n.value<std::string>())
        value = parse_quantity(*text, Dimension::frequency, error);
      else if (auto number = n.value<double>())
        value = *number;
      if (!value || !(*value > 0.0) || !std::isfinite(*value)) t.fail("frequencies", expected);
      bounds[i] = *value;
    }
    if (!(bounds[0] < bounds[1])) t.fail("frequencies", expected + " (the lower first)");
    limits.min_frequency = bounds[0];
    limits.max_frequency = bounds[1];
    t.reject_unknown_keys();
    s.table = limits;
  }
  root.reject_unknown_keys();
  return c;
}

}  // namespace

Case read_specimen(const std::filesystem::path& specimen, DiagnosisSettings* settings) {
  return specimen_from(parse_toml_file(specimen), specimen, settings);
}

Case read_specimen_text(std::string_view text, const std::filesystem::path& named_as, DiagnosisSettings* settings) {
  return specimen_from(toml::parse(text, named_as.string()), named_as, settings);
}

namespace {

// A cask rocked when its rotation passed this share of alpha (far above a standing cask's
// rotation on its springs).
constexpr double kRockedFraction = 0.1;

// A table in SI too weak for the rocking it caused: rocking starts at g tan(alpha), and a column
// in g reads about ten times smaller. Reported on the test, as its other imperfections are.
void report_table_unit(MeasuredTest& test, double alpha, double gravity) {
  if (test.table_unit_declared || !(alpha > 0.0)) return;
  double table = 0.0, rotation = 0.0;
  for (double a : test.table_acceleration)
    if (std::isfinite(a)) table = std::max(table, std::abs(a));
  for (std::size_t k = 0; k < test.rotation.size(); ++k)
    if (test.rotation_valid[k]) rotation = std::max(rotation, std::abs(test.rotation[k]));
  const double onset = gravity * std::tan(alpha);
  if (rotation > kRockedFraction * alpha && table < 0.5 * onset) {
    test.issues.push_back(test.file.filename().string() + ": table_acc: peaks at " + number_text(table) +
                          " m/s^2, under half of g tan(alpha) = " + number_text(onset) +
                          " m/s^2, the least that makes this cask rock, yet theta reaches " + number_text(rotation) +
                          " rad: a column in g? declare it in the header, e.g. 'table_acc [g]'");
  }
}

}  // namespace

MeasuredSet read_measured_set(const std::filesystem::path& directory) {
  MeasuredSet set;
  set.directory = directory;
  if (!std::filesystem::is_directory(directory)) {
    throw InputError(located(directory, 0, "not a directory; expected a measured-data directory with specimen.toml and CSV files"));
  }
  const std::filesystem::path specimen = directory / "specimen.toml";
  set.specimen = read_specimen(specimen, &set.settings);

  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    if (entry.is_regular_file() && entry.path().extension() == ".csv") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  // Each file first: what is wrong inside a file says more than how many files there are.
  for (const auto& file : files) set.tests.push_back(read_measured_test(file));
  if (files.size() < 2) {
    throw InputError(located(directory, 0, "found " + std::to_string(files.size()) +
                                               " test files (*.csv); a diagnosis needs at least 2 (one to fit, one to check)"));
  }

  set.vertical_measured = std::all_of(set.tests.begin(), set.tests.end(), [](const MeasuredTest& t) { return t.has_vertical; });
  for (int i = 0; i < static_cast<int>(set.tests.size()); ++i) {
    const std::string& name = set.tests[i].name;
    const bool held = set.settings.heldout.empty()
                          ? i % 3 == 1
                          : std::find(set.settings.heldout.begin(), set.settings.heldout.end(), name) != set.settings.heldout.end();
    (held ? set.heldout : set.training).push_back(i);
  }
  for (const std::string& name : set.settings.heldout) {
    if (std::none_of(set.tests.begin(), set.tests.end(), [&](const MeasuredTest& t) { return t.name == name; })) {
      throw InputError(located(specimen, 0, "key diagnosis.heldout: no test named \"" + name + "\""));
    }
  }
  if (set.training.empty() || set.heldout.empty()) {
    throw InputError(located(specimen, 0, "the tests must split into a training and a held-out part; got " +
                                              std::to_string(set.training.size()) + " and " +
                                              std::to_string(set.heldout.size())));
  }
  // A specimen that no model can be built from (a time step beyond the stability limit, a
  // mechanism its section cannot take) is refused now, naming its file, not minutes into a fit.
  std::vector<std::vector<Mechanism>> variants = {{}};
  for (Mechanism m : all_mechanisms()) variants.push_back({m});
  double alpha = 0.0, gravity = 0.0;
  for (const std::vector<Mechanism>& mechanisms : variants) {
    try {
      const ModelVariant variant(set.specimen, mechanisms, set.vertical_measured);
      if (mechanisms.empty()) alpha = variant.model().stability_angle, gravity = variant.model().gravity;
    } catch (const std::invalid_argument& e) {
      throw InputError(located(specimen, 0, std::string(e.what()) +
                                                (mechanisms.empty() ? "" : " (with " + mechanism_name(mechanisms[0]) + ")")));
    }
  }
  for (MeasuredTest& test : set.tests) report_table_unit(test, alpha, gravity);
  return set;
}

}  // namespace caskdem::diagnosis
