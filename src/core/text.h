#pragma once
// Reading the text files users bring (accelerograms, measured tests): one place that turns a
// file into lines and a token into a number, with the same checks and messages for both.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace caskdem {

// Without leading and trailing white space.
std::string_view trim(std::string_view s);

// In lower case (ASCII), for names compared without case.
std::string lower_case(std::string_view s);

// The largest text input read (a case, an ensemble, a record, a measured test): far above
// any real one (a 1e5-sample record is a few MB), so a wrong path is refused, not read.
inline constexpr std::uintmax_t kLargestTextFile = 256u << 20;

// Before a file is opened: an InputError naming it unless it is a regular file (a missing
// path, a directory, a device such as /dev/zero, a FIFO or a socket would fail late, hang or
// read without end) of at most `largest` bytes; `expected` says what was wanted.
void require_regular_file(const std::filesystem::path& file, const std::string& expected,
                          std::uintmax_t largest = kLargestTextFile);

// The file's lines, without line ends (LF or CRLF) and without a UTF-8 byte-order mark. A
// missing, unreadable, UTF-16 or binary file is an InputError naming the file (and line) and
// saying that `expected` was expected (e.g. "a measured-test CSV file").
std::vector<std::string> read_text_lines(const std::filesystem::path& file, const std::string& expected);

// The whole token as a double, a leading '+' allowed; a value beyond the range of a double is
// infinity (one below it 0) and "nan"/"inf" parse (callers reject what is not finite); nullopt otherwise.
std::optional<double> parse_double(std::string_view token);

// A number for a message: six significant digits, as %g (1e-09, 0.35, 2.38e+07), so that a
// small or large value is not printed as 0.000000 or as 309 digits.
std::string number_text(double x);

// For a name the reader does not know (a column, a key): the candidate it most likely
// misspells, compared without case by edit distance (Levenshtein: insertions, deletions,
// substitutions), when within 1 edit for names of up to 4 letters and 2 beyond, or when one
// name of at least 3 letters begins with the other ("table_acc_vert"); nullopt otherwise.
std::optional<std::string> likely_meant(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace caskdem
