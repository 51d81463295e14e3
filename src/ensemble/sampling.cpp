#include "ensemble/sampling.h"

#include <algorithm>
#include <numeric>

#include <Random123/boxmuller.hpp>
#include <Random123/philox.h>
#include <Random123/u01fixedpt.h>

namespace caskdem {

namespace {
// Streams of the counter's last word, so different uses never share numbers.
constexpr std::uint64_t kSampleStream = 0;
constexpr std::uint64_t kPermutationStream = 1;
}  // namespace

double philox_uniform(std::uint64_t seed, std::uint64_t a, std::uint64_t b, std::uint64_t c) {
  using Philox = r123::Philox4x32;
  const Philox::key_type key = {{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)}};
  const Philox::ctr_type counter = {{static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(a >> 32),
                                     static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(c)}};
  const Philox::ctr_type out = Philox()(counter, key);
  const std::uint64_t bits = (std::uint64_t(out[0]) << 32) | out[1];
  return u01fixedpt_open_open_64_double(bits);
}

double philox_normal(std::uint64_t seed, const std::array<std::uint32_t, 4>& words) {
  using Philox = r123::Philox4x32;
  const Philox::key_type key = {{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)}};
  const Philox::ctr_type counter = {{words[0], words[1], words[2], words[3]}};
  const Philox::ctr_type out = Philox()(counter, key);
  return r123::boxmuller((std::uint64_t(out[0]) << 32) | out[1], (std::uint64_t(out[2]) << 32) | out[3]).x;
}

Sampler::Sampler(SamplingMethod method, std::uint64_t seed, int stripes, std::int64_t per_stripe, int dimensions)
    : method_(method), seed_(seed), per_stripe_(per_stripe), dimensions_(dimensions) {
  if (method_ != SamplingMethod::latin_hypercube) return;
  strata_.resize(static_cast<std::size_t>(stripes) * dimensions * per_stripe);
  std::vector<double> keys(per_stripe);
  std::vector<std::int64_t> order(per_stripe);
  for (int s = 0; s < stripes; ++s) {
    for (int d = 0; d < dimensions; ++d) {
      // A random permutation: rank independent uniform keys (ties have probability 2^-64).
      const std::uint64_t column = std::uint64_t(s) * 1024 + d;
      for (std::int64_t j = 0; j < per_stripe; ++j) keys[j] = philox_uniform(seed_, column, j, kPermutationStream << 16);
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](std::int64_t x, std::int64_t y) { return keys[x] < keys[y]; });
      std::int64_t* strata = &strata_[(static_cast<std::size_t>(s) * dimensions + d) * per_stripe];
      for (std::int64_t rank = 0; rank < per_stripe; ++rank) strata[order[rank]] = rank;
    }
  }
}

double Sampler::uniform(int stripe, std::int64_t position, int dimension) const {
  const std::uint64_t column = std::uint64_t(stripe) * 1024 + dimension;
  const double u = philox_uniform(seed_, column, position, kSampleStream);
  if (method_ == SamplingMethod::monte_carlo) return u;
  const std::int64_t stratum = strata_[(static_cast<std::size_t>(stripe) * dimensions_ + dimension) * per_stripe_ + position];
  return (static_cast<double>(stratum) + u) / static_cast<double>(per_stripe_);
}

}  // namespace caskdem
