#pragma once
// Checks of command-line values, shared by the subcommands. CLI11's own number checks let NaN
// through and print their bounds with %f (the largest double as 309 digits); these say what
// was expected in words and refuse NaN and infinities.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include <CLI/CLI.hpp>

#include "core/text.h"

namespace caskdem::commands {

// A finite number for which `acceptable` holds; otherwise "expected WHAT, got TEXT".
inline CLI::Validator number_check(const std::string& what, std::function<bool(double)> acceptable,
                                   const std::string& name) {
  return CLI::Validator(
      [what, acceptable](std::string& text) -> std::string {
        const std::optional<double> value = parse_double(trim(text));
        if (!value || !std::isfinite(*value) || !acceptable(*value)) return "expected " + what + ", got \"" + text + "\"";
        return "";
      },
      name);
}

inline CLI::Validator positive_number() {
  return number_check("a finite number above zero", [](double x) { return x > 0.0; }, "POSITIVE");
}

inline CLI::Validator non_negative_number() {
  return number_check("a finite number, zero or more", [](double x) { return x >= 0.0; }, "NONNEGATIVE");
}

// More OpenMP threads than this is a typing error (and libgomp fails creating them).
inline constexpr int kMostThreads = 1024;

inline CLI::Validator thread_count() {
  return number_check("a whole number of threads from 0 (all cores) to " + std::to_string(kMostThreads),
                      [](double x) { return x >= 0.0 && x <= kMostThreads && x == std::floor(x); }, "THREADS");
}

// A seed: a whole number from 0 to 2^64 - 1, digits only (CLI11 would wrap "-3" and clamp
// what overflows).
inline CLI::Validator seed_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::string_view digits = trim(text);
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (digits.empty() || error != std::errc() || end != digits.data() + digits.size())
          return "expected a seed, a whole number from 0 to 18446744073709551615, got \"" + text + "\"";
        return "";
      },
      "SEED");
}

// A range [low, high] of finite numbers, `what` naming the quantity and its unit.
inline CLI::Validator number_within(const std::string& what, double low, double high) {
  return number_check(what + " from " + number_text(low) + " to " + number_text(high),
                      [low, high](double x) { return x >= low && x <= high; }, "NUMBER");
}

}  // namespace caskdem::commands
