#pragma once
// The resampling units of the step studies' paired bootstrap (bench/timestep_convergence.cpp,
// bench/bench_peer_fragility.cpp): one replicate of the realisations' indices, drawn once and
// used for every step so that the steps' differences are paired. Records resampled with all
// their realisations is the record-to-record band an ensemble of several motions reports
// (ensemble/fragility.h); each stripe's realisations resampled is the band with the records fixed.

#include <cstdint>
#include <random>
#include <vector>

namespace caskdem::bench {

// by_motion[m]: the indices of motion m's realisations; a replicate of as many motions, drawn
// with replacement, each with all of them.
inline std::vector<std::int64_t> resample_motions(const std::vector<std::vector<std::int64_t>>& by_motion,
                                                  std::mt19937_64& random) {
  std::vector<std::int64_t> sample;
  std::uniform_int_distribution<std::size_t> pick(0, by_motion.size() - 1);
  for (std::size_t m = 0; m < by_motion.size(); ++m) {
    const auto& chosen = by_motion[pick(random)];
    sample.insert(sample.end(), chosen.begin(), chosen.end());
  }
  return sample;
}

// by_stripe[j]: the indices of stripe j's realisations; each stripe's drawn with replacement.
inline std::vector<std::int64_t> resample_stripes(const std::vector<std::vector<std::int64_t>>& by_stripe,
                                                  std::mt19937_64& random) {
  std::vector<std::int64_t> sample;
  for (const auto& stripe : by_stripe) {
    std::uniform_int_distribution<std::size_t> pick(0, stripe.size() - 1);
    for (std::size_t k = 0; k < stripe.size(); ++k) sample.push_back(stripe[pick(random)]);
  }
  return sample;
}

}  // namespace caskdem::bench
