// Ensemble result files as `plot` and `--resume` read them: the seal first, then HDF5.
#include "ensemble/results.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace caskdem;
  const auto file = fuzz::write_input("results.h5", data, size);
  fuzz::expect_refusal_or_success([&] { verify_ensemble_file(file); });
  return 0;
}
