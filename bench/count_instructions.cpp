// The kernel benchmark's work, once, for an instruction counter: the instructions a
// realisation-step costs are what callgrind counts inside advance_block over the
// realisation-steps this prints. Instructions per realisation-step over the cycles one takes
// (clock / measured realisation-steps per second) is the instructions per cycle the core
// reaches, the number that says how far the kernel is from what the core can issue.
//
//   valgrind --tool=callgrind --toggle-collect='caskdem::advance_block*'
//            --callgrind-out-file=kernel.callgrind build/bench/count_instructions avx2 exponential
//   callgrind_annotate kernel.callgrind | head     ("PROGRAM TOTALS" is the instruction count)

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_common.h"

namespace caskdem::bench {
namespace {

FrictionLaw friction_law_named(const std::string& name) {
  if (name == "constant") return FrictionLaw::constant;
  if (name == "static_kinetic") return FrictionLaw::static_kinetic;
  if (name == "exponential") return FrictionLaw::exponential;
  throw std::invalid_argument("friction law \"" + name + "\": expected constant, static_kinetic or exponential");
}

int run(const std::string& isa_name, const std::string& law_name) {
  const InstructionSet isa = parse_instruction_set(isa_name);
  if (!instruction_set_available(isa)) throw std::invalid_argument(isa_name + " is not available on this machine");
  const Case c = paper_model(friction_law_named(law_name));
  const Model model = build_model(c.model, c.parameters);
  const std::vector<double> table = table_acceleration(model.time_step, kKernelSteps);
  const std::vector<double> still(kKernelSteps, 0.0);
  LaneBlock block = make_block(model, c.parameters, kKernelLanes);
  advance_block(isa, model, block, table.data(), still.data(), 0, kKernelSteps);
  std::printf("%s, %s friction: %d lanes x %d steps = %lld realisation-steps\n", isa_name.c_str(), law_name.c_str(),
              kKernelLanes, kKernelSteps, static_cast<long long>(kKernelLanes) * kKernelSteps);
  return 0;
}

}  // namespace
}  // namespace caskdem::bench

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s INSTRUCTION_SET FRICTION_LAW   (e.g. avx2 exponential)\n", argv[0]);
    return 2;
  }
  try {
    return caskdem::bench::run(argv[1], argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "count_instructions: %s\n", e.what());
    return 2;
  }
}
