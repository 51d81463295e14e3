// A measured-data directory's specimen.toml, read with two fixed, valid tests beside it
// (fuzz/data/measured), as `caskdem diagnose` reads the directory before any fit.
#include "diagnosis/measured_set.h"
#include "fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace caskdem;
  static const std::filesystem::path directory = [] {
    const auto d = fuzz::work_directory() / "measured";
    std::filesystem::create_directories(d);
    for (const char* test : {"test1.csv", "test2.csv"}) {
      std::filesystem::copy_file(std::filesystem::path(CASKDEM_FUZZ_DATA) / "measured" / test, d / test,
                                 std::filesystem::copy_options::overwrite_existing);
    }
    return d;
  }();
  std::ofstream(directory / "specimen.toml", std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  fuzz::expect_refusal_or_success([&] { (void)diagnosis::read_measured_set(directory); });
  return 0;
}
