#pragma once
// Counter-based random numbers for the ensemble: every uniform number is a pure function
// of (seed, realisation, dimension), computed with Random123's Philox4x32-10 (Salmon et
// al., "Parallel random numbers: as easy as 1, 2, 3", SC11). Any realisation can be
// re-run alone, and nothing depends on threads, blocks, ranks or the order of work.
//
//   monte_carlo      u = U(seed; stripe, position, dimension)
//   latin_hypercube  within each stripe of n realisations and for each dimension, the n
//                    values fall one in each of the n equal strata of (0, 1):
//                    u = (pi(position) + U(...)) / n, pi a random permutation drawn from
//                    the same generator (McKay, Beckman & Conover 1979)

#include <array>
#include <cstdint>
#include <vector>

namespace caskdem {

enum class SamplingMethod { monte_carlo, latin_hypercube };

// A uniform number in the open interval (0, 1) from the counter (a, b, c) under the key seed.
double philox_uniform(std::uint64_t seed, std::uint64_t a, std::uint64_t b, std::uint64_t c);

// A standard normal number from the four counter words under the key seed (Box-Muller on the
// generator's 128 output bits).
double philox_normal(std::uint64_t seed, const std::array<std::uint32_t, 4>& words);

class Sampler {
 public:
  Sampler(SamplingMethod method, std::uint64_t seed, int stripes, std::int64_t per_stripe, int dimensions);
  double uniform(int stripe, std::int64_t position, int dimension) const;

 private:
  SamplingMethod method_;
  std::uint64_t seed_;
  std::int64_t per_stripe_;
  int dimensions_;
  std::vector<std::int64_t> strata_;  // [stripe][dimension][position] -> stratum (Latin hypercube)
};

}  // namespace caskdem
