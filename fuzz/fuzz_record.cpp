// Acceleration records: PEER .AT2 (both header forms) and column files (CSV, text), with and
// without a unit given, and a time step for single-column files.
#include "fuzz/fuzz_input.h"
#include "motion/record.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace caskdem;
  const auto file = fuzz::write_input("record.AT2", data, size);
  fuzz::expect_refusal_or_success([&] { (void)motion::read_record(file, {}); });
  motion::ReadOptions in_g;
  in_g.unit = motion::AccelerationUnit::g;
  in_g.time_step = 0.01;
  fuzz::expect_refusal_or_success([&] { (void)motion::read_record(file, in_g); });
  return 0;
}
