// caskdem_independent_data: writes a measured-data directory made with the independent
// cylinder model, for testing `caskdem diagnose` on data its own model did not make.
//   caskdem_independent_data --out DIR --effect NAME|none --seed N [--footprint distributed|gyration|radius]
//   caskdem_independent_data --out DIR --effect NAME|none --seed N --drive FILE --test K
// The second adds test K to the set in DIR (made with the same effect and seed): the table
// driven by FILE, a drive caskdem plan-test wrote (drive-1.csv), as the laboratory would run it.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

#include "measured_set.h"

namespace {

int usage(const std::string& problem) {
  std::cerr << "caskdem_independent_data: " << problem << "\n"
            << "usage: caskdem_independent_data --out DIR --effect NAME|none --seed N [--footprint "
               "distributed|gyration|radius]\n"
            << "       caskdem_independent_data --out DIR --effect NAME|none --seed N --drive FILE --test K\n"
            << "effects: none";
  for (const auto& name : independent::effect_names()) std::cerr << ", " << name;
  std::cerr << "\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out, effect, seed_text, footprint = "distributed", drive, test_text;
  bool footprint_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    std::string* target = arg == "--out"         ? &out
                          : arg == "--effect"    ? &effect
                          : arg == "--seed"      ? &seed_text
                          : arg == "--footprint" ? &footprint
                          : arg == "--drive"     ? &drive
                          : arg == "--test"      ? &test_text
                                                 : nullptr;
    if (!target) return usage("unknown argument '" + arg + "'");
    if (i + 1 >= argc) return usage(arg + " needs a value");
    *target = argv[++i];
    footprint_given = footprint_given || target == &footprint;
  }
  if (out.empty()) return usage("--out is required");
  if (effect.empty()) return usage("--effect is required");
  if (!independent::is_effect(effect)) return usage("unknown effect '" + effect + "'");
  if (seed_text.empty()) return usage("--seed is required");
  std::uint64_t seed = 0;
  try {
    std::size_t used = 0;
    if (seed_text.front() == '-') throw std::invalid_argument("negative");
    seed = std::stoull(seed_text, &used);
    if (used != seed_text.size()) throw std::invalid_argument("trailing");
  } catch (const std::exception&) {
    return usage("--seed must be a non-negative integer, not '" + seed_text + "'");
  }
  if (footprint != "distributed" && footprint != "gyration" && footprint != "radius")
    return usage("--footprint must be distributed, gyration or radius, not '" + footprint + "'");

  if (drive.empty() != test_text.empty()) return usage("--drive and --test go together");
  if (!drive.empty() && footprint_given)
    return usage("--footprint is the set's, chosen when it was written; expected it without --drive");
  if (!drive.empty()) {
    int number = 0;
    try {
      std::size_t used = 0;
      number = std::stoi(test_text, &used);
      if (used != test_text.size() || number < 1) throw std::invalid_argument("not a test number");
    } catch (const std::exception&) {
      return usage("--test must be a positive integer, not '" + test_text + "'");
    }
    try {
      const auto t = independent::add_drive_test(out, effect, seed, drive, number);
      std::printf("%s: added %s from %s  peak rotation %.4f rad  peak slide %.2f mm  final slide %.2f mm%s\n",
                  out.c_str(), t.name.c_str(), drive.c_str(), t.peak_rotation, 1e3 * t.peak_slide, 1e3 * t.final_slide,
                  t.tipped_over ? "  TIPPED OVER" : "");
    } catch (const std::exception& e) {  // a bad drive file or a set made otherwise: the input's fault
      std::cerr << "caskdem_independent_data: " << e.what() << "\n";
      return 2;
    }
    return 0;
  }

  try {
    const auto start = std::chrono::steady_clock::now();
    independent::MeasuredSetOptions options;
    options.footprint = footprint;
    const auto result = independent::write_independent_measured_set(out, effect, seed, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: effect %s, seed %llu, friction %.3f, stiffness x%.2f (%.1f s)\n", out.c_str(), effect.c_str(),
                static_cast<unsigned long long>(seed), result.truth.friction, result.truth.stiffness_scale, seconds);
    for (const auto& t : result.tests)
      std::printf("  %s  peak rotation %.4f rad  peak slide %.2f mm  final slide %.2f mm%s\n", t.name.c_str(),
                  t.peak_rotation, 1e3 * t.peak_slide, 1e3 * t.final_slide, t.tipped_over ? "  TIPPED OVER" : "");
  } catch (const std::exception& e) {
    std::cerr << "caskdem_independent_data: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
