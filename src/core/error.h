#pragma once
// One error type for bad input. Its message names where the problem is (a file and a
// line, or a TOML key) and what was expected; the command line prints it once and exits
// with a non-zero status. Everything the user can get wrong ends here, never in a crash
// or a NaN in a result file.

#include <filesystem>
#include <stdexcept>
#include <string>

namespace caskdem {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// "FILE:LINE: MESSAGE" (LINE omitted when 0), the form compilers use, so editors can jump to it.
inline std::string located(const std::filesystem::path& file, long line, const std::string& message) {
  std::string text = file.string();
  if (line > 0) text.append(":").append(std::to_string(line));
  text.append(": ").append(message);
  return text;
}

[[noreturn]] inline void fail_at(const std::filesystem::path& file, long line, const std::string& message) {
  throw InputError(located(file, line, message));
}

}  // namespace caskdem
