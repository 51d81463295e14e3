// Ensemble files: the TOML and every key's checks, as `caskdem ensemble` reads them.
#include "ensemble/ensemble_file.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace caskdem;
  const auto file = fuzz::write_input("ensemble.toml", data, size);
  fuzz::expect_refusal_or_success([&] { (void)load_ensemble(file); });
  return 0;
}
