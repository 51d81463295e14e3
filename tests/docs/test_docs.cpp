// The documentation against the tree: every relative link in README.md and docs/ points to a
// file that exists, and every key the case-file and ensemble-file readers accept is in the
// reference (docs/case-file.md, docs/ensemble-file.md) under its table. The keys come from the
// readers' own lists (case_file_keys(), ensemble_file_keys()), which the readers enforce:
// reading a key a list does not hold is a std::logic_error, tried here on every shipped case
// and ensemble and on files that take every branch of the readers.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "casefile/case_file.h"
#include "ensemble/ensemble_file.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = CASKDEM_SOURCE_DIR;

std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// README.md and every markdown file under docs/.
std::vector<fs::path> markdown_files() {
  std::vector<fs::path> files = {kSource / "README.md"};
  for (const auto& entry : fs::recursive_directory_iterator(kSource / "docs"))
    if (entry.is_regular_file() && entry.path().extension() == ".md") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The line without its inline code spans (`...`), which may hold brackets that are not links.
std::string without_code_spans(const std::string& line) {
  static const std::regex code("`[^`]*`");
  return std::regex_replace(line, code, "``");
}

struct Link {
  fs::path file;
  int line = 0;
  std::string target;
};

// Every [text](target) and ![alt](target) outside fenced code blocks.
std::vector<Link> links_in(const fs::path& file) {
  static const std::regex link(R"(\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\))");
  std::vector<Link> links;
  bool fenced = false;
  int number = 0;
  for (const std::string& raw : lines_of(file)) {
    ++number;
    const auto first = raw.find_first_not_of(' ');
    if (first != std::string::npos && raw.compare(first, 3, "```") == 0) {
      fenced = !fenced;
      continue;
    }
    if (fenced) continue;
    const std::string line = without_code_spans(raw);
    for (auto it = std::sregex_iterator(line.begin(), line.end(), link); it != std::sregex_iterator(); ++it)
      links.push_back({file, number, (*it)[1].str()});
  }
  return links;
}

TEST(Docs, EveryRelativeLinkPointsToAFileThatExists) {
  int checked = 0;
  for (const fs::path& file : markdown_files()) {
    for (const Link& link : links_in(file)) {
      const std::string& target = link.target;
      if (target.rfind("http://", 0) == 0 || target.rfind("https://", 0) == 0 || target.rfind("mailto:", 0) == 0 ||
          target.front() == '#')
        continue;
      const std::string path = target.substr(0, target.find('#'));
      ++checked;
      EXPECT_TRUE(fs::exists(file.parent_path() / path))
          << fs::relative(file, kSource).string() << ":" << link.line << ": broken link to " << target;
    }
  }
  EXPECT_GT(checked, 20) << "the README and docs/ should link to each other";
}

// The keys a reference page documents, table by table, read from its markdown tables of the
// form | table | key | meaning |: a row whose first cell names a table (`[cask]`, `[[motions]]`,
// `[uncertain.NAME]`, (top)) starts it, rows with an empty first cell continue it, and every
// `code` in the other cells counts. A `[table]` in those cells includes that table's keys.
struct Documented {
  std::map<std::string, std::set<std::string>> keys;
  std::map<std::string, std::set<std::string>> includes;

  bool has(const std::string& table, const std::string& key, int depth = 0) const {
    if (auto k = keys.find(table); k != keys.end() && k->second.count(key)) return true;
    if (auto i = includes.find(table); i != includes.end() && depth < 4)
      for (const std::string& other : i->second)
        if (has(other, key, depth + 1)) return true;
    return false;
  }
};

std::string table_name(std::string cell) {
  // "`[[motions]]`" -> "motions"; "`[uncertain.NAME]`" -> "uncertain.*"; "(top)" -> "".
  cell.erase(std::remove_if(cell.begin(), cell.end(), [](char c) { return c == '`' || c == '[' || c == ']'; }),
             cell.end());
  cell.erase(0, cell.find_first_not_of(' '));
  cell.erase(cell.find_last_not_of(' ') + 1);
  if (cell == "(top)") return "";
  if (const auto at = cell.find(".NAME"); at != std::string::npos) cell = cell.substr(0, at) + ".*";
  return cell;
}

void read_reference(const fs::path& page, Documented& documented) {
  static const std::regex code("`([^`]*)`");
  std::string table = "?";
  for (const std::string& line : lines_of(page)) {
    if (line.rfind("|", 0) != 0) {
      table = "?";
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream row(line.substr(1));
    for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
    if (cells.size() < 2 || cells[0].find("---") != std::string::npos) continue;
    if (cells[0].find_first_not_of(' ') != std::string::npos) {
      if (cells[0].find('`') == std::string::npos && cells[0].find("(top)") == std::string::npos) {
        table = "?";  // a header row, or a table of another kind
        continue;
      }
      table = table_name(cells[0]);
    }
    if (table == "?") continue;
    for (std::size_t i = 1; i < cells.size(); ++i) {
      for (auto it = std::sregex_iterator(cells[i].begin(), cells[i].end(), code); it != std::sregex_iterator(); ++it) {
        const std::string text = (*it)[1].str();
        if (text.size() > 2 && text.front() == '[' && text.back() == ']' && text.find(',') == std::string::npos)
          documented.includes[table].insert(table_name(text));
        else
          documented.keys[table].insert(text);
      }
    }
  }
}

void expect_documented(const KeySchema& schema, const std::vector<fs::path>& pages) {
  Documented documented;
  for (const fs::path& page : pages) {
    ASSERT_TRUE(fs::exists(page)) << page;
    read_reference(page, documented);
  }
  std::string where;
  for (const fs::path& page : pages) where += (where.empty() ? "" : " or ") + fs::relative(page, kSource).string();
  for (const KeyTable& t : schema) {
    const std::string shown = t.table.empty() ? "the top level" : "[" + t.table + "]";
    for (const std::string& key : t.keys) {
      // A key that holds a table ([cask], [contact.barkan]) is documented by that table's rows.
      const std::string table = t.table.empty() ? key : t.table + "." + key;
      EXPECT_TRUE(documented.has(t.table, key) || documented.keys.count(table) > 0) << "key `" << key << "` of " << shown << " is read but not documented in "
                                                << where;
    }
  }
}

TEST(Docs, EveryCaseFileKeyIsInTheReference) {
  expect_documented(case_file_keys(), {kSource / "docs" / "case-file.md"});
}

TEST(Docs, EveryEnsembleFileKeyIsInTheReference) {
  expect_documented(ensemble_file_keys(), {kSource / "docs" / "case-file.md", kSource / "docs" / "ensemble-file.md"});
}

// The key lists hold every key the readers read: each shipped file, and files that take each
// branch, load without the readers' std::logic_error.
TEST(Docs, ReadersReadOnlyTheKeysTheyList) {
  for (const auto& entry : fs::directory_iterator(kSource / "cases")) {
    if (entry.path().extension() == ".toml") {
      EXPECT_NO_THROW(load_case(entry.path())) << entry.path();
    }
  }
  for (const auto& entry : fs::directory_iterator(kSource / "ensembles")) {
    if (entry.path().extension() == ".toml") {
      EXPECT_NO_THROW(load_ensemble(entry.path())) << entry.path();
    }
  }

  testing::TestDirectory dir;
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  write("friction.csv", "speed,mu\n0,0.5\n0.1,0.4\n");
  const std::string cylinder = R"(
[cask]
shape = "cylinder"
diameter = "0.95 m"
height = "2.033 m"
mass = 12600
inertia = 5000
half_width = "radius"
eccentricity = "1 cm"
rounding = "0.5 cm"
[contact]
normal_stiffness = "2.38e3 bar/cm"
shear_stiffness = "2.21e3 bar/cm"
[damping]
ratio = 0.05
frequency = "135 Hz"
[integration]
safety_factor = 0.02
duration = "5 s"
settle_time = "1 s"
[limits]
tip_over_angle = "60 deg"
lift_off_height = "0.3 m"
pad_half_width = "2 m"
)";
  EXPECT_NO_THROW(load_case(write("polygon.toml", R"(
title = "polygon on a Barkan floor"
[cask]
shape = "polygon"
vertices = [[-0.3, 0.0], [0.3, 0.0], [0.3, 2.0], [-0.3, 2.0]]
depth = "0.8 m"
density = "8 g/cm^3"
centre_of_mass = [0.0, 1.0]
[contact.barkan]
shear_modulus = "100 MPa"
poisson_ratio = 0.3
beta_z = 2.1
beta_x = 1.0
[friction]
law = "static_kinetic"
static = 0.5
kinetic = 0.4
[damping]
ratio = 0.05
[motion]
kind = "pulse"
shape = "one_sine"
amplitude = "0.3 g"
duration = "0.2 s"
similarity_scale = 1
[motion.vertical]
kind = "sine"
amplitude = "1 mm"
frequency = "3 Hz"
cycles = 6
ramp_cycles = 1
[free_vibration]
initial_tilt_ratio = 0.4
ratios = 2
duration = "3 s"
target_restitution = 0.95
[output]
directory = "out"
interval = "2 ms"
csv = false
hdf5 = false
plot = false
)")));
  EXPECT_NO_THROW(load_case(write("record.toml", cylinder + R"(
[friction]
law = "table"
table_file = "friction.csv"
[motion]
kind = "record"
file = "record.txt"
format = "columns"
unit = "gal"
time_step = 0.01
target_pgv = "0.3 m/s"
)")));
  EXPECT_NO_THROW(load_case(write("synthetic.toml", cylinder + R"(
[friction]
law = "table"
table = [[0.0, 0.5], [0.1, 0.4]]
[motion]
kind = "synthetic"
seed = 3
duration = "10 s"
time_step = 0.01
dominant_frequency = "3 Hz"
ground_damping = 0.5
high_pass_frequency = "0.2 Hz"
high_pass_damping = 0.6
rise_time = "1 s"
strong_duration = "4 s"
decay = 0.5
pga = "0.3 g"
)")));
  EXPECT_NO_THROW(load_ensemble(write("ensemble.toml", "title = \"every ensemble table\"\n" + cylinder + R"(
[friction]
law = "exponential"
static = 0.6
kinetic = 0.45
decay_speed = "5 cm/s"
[free_vibration]
initial_tilt_ratio = 0.5
ratios = 3
[[motions]]
name = "one"
kind = "record"
file = "record.txt"
[[motions]]
kind = "synthetic"
[uncertain.friction_static]
distribution = "normal"
mean = 0.6
std = 0.05
low = 0.4
high = 0.8
[uncertain.friction_kinetic]
distribution = "uniform"
low = 0.4
high = 0.5
[uncertain.friction_decay_speed]
distribution = "constant"
value = "5 cm/s"
[uncertain.mass]
distribution = "lognormal"
median = 12600
log_std = 0.05
[uncertain.restitution]
distribution = "uniform"
low = 0.93
high = 0.96
[uncertain.centre_height]
distribution = "normal"
mean = "1 m"
std = "2 cm"
low = "0.9 m"
high = "1.1 m"
[intensity]
measure = "pgv_ratio"
levels = [0.5, 1.0]
realisations = 8
[sampling]
method = "monte_carlo"
seed = 4
[limit_states]
tip_over = true
rotation_ratio = [0.5]
sliding = ["5 cm"]
[fragility]
bootstrap = 10
confidence = 0.9
[run]
block_lanes = 16
checkpoint_interval = "5 s"
)")));
}

TEST(Docs, AReaderRefusesToReadAKeyItsListDoesNotHold) {
  const KeySchema schema = {{"", {"cask"}}, {"cask", {"mass"}}};
  const toml::table document = toml::parse("[cask]\nmass = 1.0\n");
  TableReader root(document, "listed.toml", "", 0, &schema);
  TableReader cask = root.table("cask");
  EXPECT_NO_THROW(cask.optional_quantity("mass", Dimension::mass));
  EXPECT_THROW(cask.optional_quantity("height", Dimension::length), std::logic_error);
  EXPECT_THROW(root.optional_string("title"), std::logic_error);
}

}  // namespace
}  // namespace caskdem
