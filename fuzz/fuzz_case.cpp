// Case files: the TOML, every key's checks, the model built from it and its motions, as
// `caskdem run` does before its first step.
#include "fuzz/fuzz_input.h"
#include "sim/case_run.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace caskdem;
  const auto file = fuzz::write_input("case.toml", data, size);
  fuzz::expect_refusal_or_success([&] {
    const Case c = load_case(file);
    (void)build_case_model(c);
    const CaseMotions motions = make_case_motions(c);
    (void)case_duration(c, motions);
  });
  return 0;
}
