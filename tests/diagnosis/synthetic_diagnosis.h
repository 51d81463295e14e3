#pragma once
// A full diagnosis at the shipped search settings of a synthetic measured set, from caskdem's own
// generator (src/diagnosis/synthesize.h) or the independent one (tests/independent), for the
// tests that check its answer (test_hidden_effects.cpp, test_more_diagnoses.cpp).

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "diagnosis/diagnose.h"
#include "diagnosis/report.h"
#include "diagnosis/synthesize.h"
#include "measured_set.h"  // tests/independent
#include "support/temporary_files.h"

namespace caskdem::diagnosis {

// specimen.toml in `directory` with its text `from` replaced by `to`.
inline void edit_specimen(const std::filesystem::path& directory, const std::string& from, const std::string& to) {
  const std::filesystem::path file = directory / "specimen.toml";
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("specimen.toml does not say " + from);
  text.replace(at, from.size(), to);
  std::ofstream(file) << text;
}

// With `report`, diagnosis.json and report.md are written there too (no plots).
inline Diagnosis diagnose_synthetic(const std::vector<Mechanism>& hidden, std::uint64_t seed, bool second_effect,
                                    const std::string& stated_rule = "gyration",
                                    const std::filesystem::path& report = {},
                                    NormalLaw data_law = NormalLaw::linear, bool compare_normal_laws = false) {
  const testing::TestDirectory directory;
  SyntheticSpec spec;
  spec.hidden = hidden;
  spec.seed = seed;
  spec.normal_law = data_law;
  write_synthetic_measured_set(directory.path(), spec);
  if (stated_rule != "gyration") {  // the data's own rule; the specimen file states another
    edit_specimen(directory.path(), "half_width = \"gyration\"", "half_width = \"" + stated_rule + "\"");
  }
  const MeasuredSet set = read_measured_set(directory.path());
  DiagnosisOptions options;
  options.threads = 2;
  options.look_for_second_effect = second_effect;
  options.compare_normal_laws = compare_normal_laws;
  Diagnosis d = diagnose(set, options);
  if (!report.empty()) write_diagnosis(report, set, d, options.isa, false);
  return d;
}

inline const CandidateScore& score_of(const Diagnosis& d, Mechanism m) {
  for (const CandidateScore& c : d.ranking) {
    if (c.mechanism == m) return c;
  }
  throw std::logic_error("not ranked");
}

// Data its own model did not make: the independent generator (tests/independent: a cylinder on
// a distributed Hunt-Crossley footprint, tanh-regularised friction, Boost.Odeint's adaptive
// Runge-Kutta; six tests of 10 mm sines and time-compressed records), its effects written apart
// from src/diagnosis/mechanisms. Rates over more seeds are in docs/diagnosis-accuracy.md.
// footprint_points > 0: specimen.toml states that many points of the distributed footprint.
inline Diagnosis diagnose_independent(const std::string& effect, std::uint64_t seed, const std::string& stated_footprint,
                                      int footprint_points = 0, bool compare_normal_laws = false) {
  const testing::TestDirectory directory;
  independent::MeasuredSetOptions options;
  options.footprint = stated_footprint;
  independent::write_independent_measured_set(directory.path(), effect, seed, options);
  if (footprint_points > 0) {
    const std::string rule = "footprint = \"distributed\"\n";
    edit_specimen(directory.path(), rule, rule + "footprint_points = " + std::to_string(footprint_points) + "\n");
  }
  const MeasuredSet set = read_measured_set(directory.path());
  DiagnosisOptions diagnosis_options;
  diagnosis_options.threads = 2;
  diagnosis_options.look_for_second_effect = false;
  diagnosis_options.compare_normal_laws = compare_normal_laws;
  return diagnose(set, diagnosis_options);
}

}  // namespace caskdem::diagnosis
