#include "casefile/toml_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/text.h"

namespace caskdem {

toml::table parse_toml_file(const std::filesystem::path& file) {
  require_regular_file(file, "a TOML file");
  try {
    return toml::parse_file(file.string());
  } catch (const toml::parse_error& error) {
    std::ostringstream message;
    message << "not valid TOML: " << error.description() << " (column " << error.source().begin.column << ")";
    throw InputError(located(file, static_cast<long>(error.source().begin.line), message.str()));
  }
}

const KeyTable* find_key_table(const KeySchema& schema, std::string_view prefix) {
  std::string path;  // the prefix without array indices
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    if (prefix[i] == '[') {
      i = prefix.find(']', i);
      if (i == std::string_view::npos) break;
      continue;
    }
    path += prefix[i];
  }
  for (const KeyTable& t : schema)
    if (t.table == path) return &t;
  const auto dot = path.rfind('.');
  if (dot == std::string::npos) return nullptr;
  const std::string any = path.substr(0, dot) + ".*";
  for (const KeyTable& t : schema)
    if (t.table == any) return &t;
  return nullptr;
}

TableReader::TableReader(const toml::table& table, std::filesystem::path file, std::string prefix, long line,
                         const KeySchema* schema)
    : table_(table), file_(std::move(file)), prefix_(std::move(prefix)), line_(line), schema_(schema) {}

bool TableReader::has(std::string_view key) const { return table_.contains(key); }

std::string TableReader::key_path(std::string_view key) const {
  return prefix_.empty() ? std::string(key) : prefix_ + "." + std::string(key);
}

long TableReader::line_of(std::string_view key) const {
  const toml::node* n = table_.get(key);
  return n ? static_cast<long>(n->source().begin.line) : line_;
}

const toml::node* TableReader::node(std::string_view key) const { return table_.get(key); }

void TableReader::mark(std::string_view key) {
  if (schema_) {
    const KeyTable* known = find_key_table(*schema_, prefix_);
    if (!known || std::find(known->keys.begin(), known->keys.end(), key) == known->keys.end()) {
      throw std::logic_error("the reader reads key " + key_path(key) +
                             ", which its list of known keys does not hold: add it there and to the reference in docs/");
    }
  }
  read_.insert(std::string(key));
}

void TableReader::missing(std::string_view key, const std::string& expected) const {
  std::vector<std::string> unread;
  for (const auto& [k, value] : table_)
    if (read_.count(k.str()) == 0) unread.emplace_back(k.str());
  const auto meant = likely_meant(key, unread);
  throw InputError(
      located(file_, line_,
              "missing key " + key_path(key) + ": expected " + expected +
                  (meant ? " (is " + *meant + (line_of(*meant) > 0 ? ", line " + std::to_string(line_of(*meant)) : "") +
                               ", a misspelling of it?)"
                         : "")));
}

void TableReader::fail(std::string_view key, const std::string& message) const {
  throw InputError(located(file_, line_of(key), "key " + key_path(key) + ": " + message));
}

std::optional<double> TableReader::optional_quantity(std::string_view key, Dimension dimension) {
  mark(key);
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  if (auto v = n->value<double>(); v && (n->is_floating_point() || n->is_integer())) {
    if (!std::isfinite(*v)) fail(key, "expected a finite number, got " + number_text(*v));
    return *v;
  }
  if (auto text = n->value<std::string>()) {
    std::string error;
    if (auto v = parse_quantity(*text, dimension, error)) return v;
    fail(key, error);
  }
  std::string example = std::string(units_of(dimension).size() > 1 ? units_of(dimension)[1].name : "");
  fail(key, "expected " + dimension_name(dimension) + " (a number in SI units" +
                (example.empty() ? "" : " or a string such as \"1.0 " + example + "\"") + ")");
}

double TableReader::quantity(std::string_view key, Dimension dimension) {
  if (!has(key)) missing(key, dimension_name(dimension));
  return *optional_quantity(key, dimension);
}

double TableReader::quantity_or(std::string_view key, Dimension dimension, double fallback) {
  return optional_quantity(key, dimension).value_or(fallback);
}

std::optional<std::string> TableReader::optional_string(std::string_view key) {
  mark(key);
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  if (auto v = n->value<std::string>()) return *v;
  fail(key, "expected a string in quotes");
}

std::string TableReader::string(std::string_view key) {
  if (!has(key)) missing(key, "a string");
  return *optional_string(key);
}

std::string TableReader::choice(std::string_view key, const std::vector<std::string>& allowed, std::string fallback) {
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
  std::optional<std::string> value = optional_string(key);
  if (!value) {
    if (!fallback.empty()) return fallback;
    missing(key, "one of " + list);
  }
  // Without case: "PGV" is pgv, as risk's --imt and --measure take it.
  const auto lower = [](std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
  };
  for (const std::string& a : allowed) {
    if (lower(*value) == lower(a)) return a;
  }
  fail(key, "expected one of " + list + ", got \"" + *value + "\"");
}

bool TableReader::boolean_or(std::string_view key, bool fallback) {
  mark(key);
  const toml::node* n = node(key);
  if (!n) return fallback;
  if (auto v = n->value<bool>(); v && n->is_boolean()) return *v;
  fail(key, "expected true or false");
}

std::optional<long> TableReader::optional_integer(std::string_view key) {
  mark(key);
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  if (n->is_integer()) return static_cast<long>(*n->value<std::int64_t>());
  fail(key, "expected a whole number");
}

long TableReader::integer(std::string_view key) {
  if (!has(key)) missing(key, "a whole number");
  return *optional_integer(key);
}

std::vector<std::pair<double, double>> TableReader::pairs(std::string_view key) {
  mark(key);
  const toml::node* n = node(key);
  std::vector<std::pair<double, double>> out;
  const toml::array* rows = n ? n->as_array() : nullptr;
  if (!rows) fail(key, "expected an array of pairs such as [[0.0, 1.0], [1.0, 2.0]]");
  for (const toml::node& row : *rows) {
    const toml::array* pair = row.as_array();
    if (!pair || pair->size() != 2) fail(key, "expected an array of pairs such as [[0.0, 1.0], [1.0, 2.0]]");
    auto a = (*pair)[0].value<double>();
    auto b = (*pair)[1].value<double>();
    if (!a || !b || !std::isfinite(*a) || !std::isfinite(*b)) {
      throw InputError(located(file_, static_cast<long>(row.source().begin.line),
                               "key " + key_path(key) + ": expected two finite numbers in each pair"));
    }
    out.emplace_back(*a, *b);
  }
  return out;
}

std::optional<std::pair<double, double>> TableReader::optional_pair(std::string_view key) {
  mark(key);
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const toml::array* pair = n->as_array();
  std::optional<double> a, b;
  if (pair && pair->size() == 2) {
    a = (*pair)[0].value<double>();
    b = (*pair)[1].value<double>();
  }
  if (!a || !b || !std::isfinite(*a) || !std::isfinite(*b)) fail(key, "expected a pair of finite numbers [x, y]");
  return std::make_pair(*a, *b);
}

bool TableReader::has_table(std::string_view key) const {
  const toml::node* n = node(key);
  return n && n->is_table();
}

TableReader TableReader::table(std::string_view key) {
  mark(key);
  const toml::node* n = node(key);
  if (!n || !n->is_table()) {
    throw InputError(located(file_, n ? static_cast<long>(n->source().begin.line) : line_,
                             "expected a table [" + key_path(key) + "]"));
  }
  return TableReader(*n->as_table(), file_, key_path(key), static_cast<long>(n->source().begin.line), schema_);
}

double TableReader::positive(std::string_view key, double value) const {
  if (!(value > 0.0)) fail(key, "expected a positive value, got " + number_text(value));
  return value;
}

double TableReader::non_negative(std::string_view key, double value) const {
  if (!(value >= 0.0)) fail(key, "expected a non-negative value, got " + number_text(value));
  return value;
}

double TableReader::in_range(std::string_view key, double value, double low, double high) const {
  if (!(value >= low && value <= high)) {
    fail(key, "expected a value between " + number_text(low) + " and " + number_text(high) + ", got " +
                  number_text(value));
  }
  return value;
}

void TableReader::reject_unknown_keys() const {
  for (const auto& [key, value] : table_) {
    if (read_.count(key.str()) == 0) {
      std::string known;
      std::vector<std::string> unused;  // known keys the table lacks: what a misspelling meant
      for (const std::string& k : read_) {
        known += (known.empty() ? "" : ", ") + k;
        if (!table_.contains(k)) unused.push_back(k);
      }
      const auto meant = likely_meant(key.str(), unused);
      throw InputError(located(file_, static_cast<long>(value.source().begin.line),
                               "unknown key " + key_path(key.str()) + (meant ? "; did you mean " + *meant + "?" : "") +
                                   (known.empty() ? "" : " (known here: " + known + ")")));
    }
  }
}

std::filesystem::path resolve_beside(const std::filesystem::path& file, const std::string& path) {
  std::filesystem::path p(path);
  if (p.is_absolute()) return p;
  return file.parent_path() / p;
}

}  // namespace caskdem
