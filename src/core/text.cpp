#include "core/text.h"

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

std::vector<std::string> read_text_lines(const std::filesystem::path& file, const std::string& expected) {
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (!std::filesystem::exists(status)) fail_at(file, 0, "no such file; expected the path of " + expected);
  if (std::filesystem::is_directory(status)) fail_at(file, 0, "is a directory; expected " + expected);
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

}  // namespace caskdem
