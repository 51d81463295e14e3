#pragma once
// Strict reading of a TOML table: every value is checked for its type, unit and range, and
// every key the program does not know is an error. Each error names the file, the line and
// the key ("cask.mass") and says what was expected.

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "core/quantity.h"

namespace caskdem {

// The keys a reader accepts, table by table. `table` is "" for the top level, a dotted path
// for a nested table ("motion.vertical"), an array's name for each of its tables ("motions"
// for [[motions]]), and a path ending in "*" for every table under one ("uncertain.*").
// A TableReader given such a list treats reading a key it does not hold as a program error
// (std::logic_error), so the list cannot fall behind the reader; the reference pages in docs/
// are checked against it (tests/docs/test_docs.cpp).
struct KeyTable {
  std::string table;
  std::vector<std::string> keys;
};
using KeySchema = std::vector<KeyTable>;

// The keys `schema` lists for the table at `prefix` ("motions[2]" is "motions"), or null.
const KeyTable* find_key_table(const KeySchema& schema, std::string_view prefix);

// Parses a TOML file; a syntax error becomes an InputError with toml++'s line and column.
toml::table parse_toml_file(const std::filesystem::path& file);

class TableReader {
 public:
  TableReader(const toml::table& table, std::filesystem::path file, std::string prefix, long line = 0,
              const KeySchema* schema = nullptr);

  const std::filesystem::path& file() const { return file_; }
  const KeySchema* schema() const { return schema_; }
  bool has(std::string_view key) const;
  std::string key_path(std::string_view key) const;  // "cask.mass"
  long line_of(std::string_view key) const;           // line of the key's value (0 if absent)

  // Quantities: a number (SI) or "value unit". Ranges are checked by the callers with require().
  double quantity(std::string_view key, Dimension dimension);
  std::optional<double> optional_quantity(std::string_view key, Dimension dimension);
  double quantity_or(std::string_view key, Dimension dimension, double fallback);

  std::string string(std::string_view key);
  std::optional<std::string> optional_string(std::string_view key);
  std::string choice(std::string_view key, const std::vector<std::string>& allowed, std::string fallback = "");
  bool boolean_or(std::string_view key, bool fallback);
  long integer(std::string_view key);
  std::optional<long> optional_integer(std::string_view key);
  std::vector<std::pair<double, double>> pairs(std::string_view key);  // [[a, b], ...]
  std::optional<std::pair<double, double>> optional_pair(std::string_view key);  // [a, b]

  bool has_table(std::string_view key) const;
  TableReader table(std::string_view key);

  // An error about a key of this table.
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;
  // Range checks with the standard message.
  double positive(std::string_view key, double value) const;
  double non_negative(std::string_view key, double value) const;
  double in_range(std::string_view key, double value, double low, double high) const;

  // Marks a key as known when the caller reads its value through toml++ itself.
  void accept(std::string_view key) { mark(key); }

  // Unknown keys are errors: call when every known key has been read.
  void reject_unknown_keys() const;

 private:
  const toml::node* node(std::string_view key) const;
  void mark(std::string_view key);
  // A required key that is absent; names a key of the table that may be it misspelt.
  [[noreturn]] void missing(std::string_view key, const std::string& expected) const;

  const toml::table& table_;
  std::filesystem::path file_;
  std::string prefix_;
  long line_;
  std::set<std::string, std::less<>> read_;
  const KeySchema* schema_ = nullptr;
};

// A path in a case file is relative to the file's directory.
std::filesystem::path resolve_beside(const std::filesystem::path& file, const std::string& path);

}  // namespace caskdem
