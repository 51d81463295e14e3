// Measured tests: the CSV of a shaking-table test (t, table_acc, theta, slide, ...).
#include "diagnosis/measured_test.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace caskdem;
  const auto file = fuzz::write_input("test1.csv", data, size);
  fuzz::expect_refusal_or_success([&] { (void)diagnosis::read_measured_test(file); });
  return 0;
}
