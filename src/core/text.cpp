#include "core/text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <sstream>
#include <fstream>
#include <iterator>
#include <limits>
#include <system_error>

#include "core/error.h"

namespace caskdem {

std::string_view trim(std::string_view s) {
  const auto is_space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::string lower_case(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

void require_regular_file(const std::filesystem::path& file, const std::string& expected, std::uintmax_t largest) {
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (!std::filesystem::exists(status)) fail_at(file, 0, "no such file; expected the path of " + expected);
  if (std::filesystem::is_directory(status)) fail_at(file, 0, "is a directory; expected " + expected);
  if (!std::filesystem::is_regular_file(status)) {
    fail_at(file, 0, "is not a regular file (a device, a FIFO or a socket); expected " + expected);
  }
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec) fail_at(file, 0, "its size cannot be read; expected " + expected + " that can be read");
  if (size > largest) {
    fail_at(file, 0, "is " + std::to_string(size) + " bytes, more than the " + std::to_string(largest) +
                         " read at most; expected " + expected);
  }
}

std::vector<std::string> read_text_lines(const std::filesystem::path& file, const std::string& expected) {
  require_regular_file(file, expected);
  std::ifstream in(file, std::ios::binary);
  if (!in) fail_at(file, 0, "cannot be opened for reading; expected " + expected + " that can be read");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) fail_at(file, 0, "could not be read; expected " + expected + " that can be read");

  if (text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF"))
    fail_at(file, 1, "the file is UTF-16 text; expected ASCII or UTF-8 text");
  if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);

  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find('\0') != std::string::npos)
      fail_at(file, static_cast<long>(lines.size() + 1), "binary data (a NUL byte); expected a text file");
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

std::optional<double> parse_double(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return std::nullopt;
  double value = 0.0;
  const char* last = token.data() + token.size();
  const auto [end, error] = std::from_chars(token.data(), last, value);
  if (end != last) return std::nullopt;
  // Beyond a double's range: strtod says which way (+-infinity on overflow, 0 on underflow).
  if (error == std::errc::result_out_of_range) return std::strtod(std::string(token).c_str(), nullptr);
  if (error != std::errc()) return std::nullopt;
  return value;
}

std::string number_text(double x) {
  std::ostringstream out;
  out.precision(6);
  out << x;
  return out.str();
}

namespace {

// Levenshtein distance by the two-row dynamic programme (Wagner & Fischer 1974).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({substitution, previous[j] + 1, current[j - 1] + 1});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

}  // namespace

std::optional<std::string> likely_meant(std::string_view name, const std::vector<std::string>& candidates) {
  const std::string given = lower_case(trim(name));
  if (given.empty()) return std::nullopt;
  const std::size_t allowed = given.size() <= 4 ? 1 : 2;
  std::optional<std::string> best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (const std::string& candidate : candidates) {
    const std::string known = lower_case(candidate);
    if (known == given) continue;
    const std::size_t distance = edit_distance(given, known);
    const std::string_view shorter = given.size() < known.size() ? given : known;
    const std::string_view longer = given.size() < known.size() ? known : given;
    const bool begins_with = shorter.size() >= 3 && longer.substr(0, shorter.size()) == shorter;
    if ((distance <= allowed || begins_with) && distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace caskdem
