// Hazard curves: OpenQuake and nshmp-haz CSV and tables, read as a user's file and, when read,
// convolved with a fragility; the annual frequency must then be finite and at least 0.
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "fuzz/fuzz_input.h"
#include "risk/annual_frequency.h"
#include "risk/hazard_curve.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace caskdem;
  const auto file = fuzz::write_input("hazard.csv", data, size);
  risk::HazardReadOptions options;
  for (int pass = 0; pass < 2; ++pass) {
    // The second pass names the measure, as --imt does for an nshmp-haz file outside its folder.
    if (pass == 1) options.measure = risk::parse_intensity_measure("PGA");
    fuzz::expect_refusal_or_success([&] {
      const risk::HazardCurve curve = risk::read_hazard_curve(file, options);
      try {
        risk::check_hazard_curve(curve);  // a curve the reader accepts, the integral takes
      } catch (const std::invalid_argument& e) {
        std::cerr << "the reader accepted a curve the integral refuses: " << e.what() << "\n";
        std::abort();
      }
      try {
        const double median = std::sqrt(curve.intensity.front() * curve.intensity.back());
        const risk::SiteRisk r = risk::site_risk(curve, {median, 0.4, 0.3});
        if (!std::isfinite(r.mean) || r.mean < 0.0 || !std::isfinite(r.fractile_95) || !std::isfinite(r.fractile_05)) {
          std::cerr << "a non-finite or negative annual frequency: " << r.mean << "\n";
          std::abort();
        }
      } catch (const std::invalid_argument&) {
        // a curve that does not cover the fragility: the command refuses it, naming the file
      }
    });
  }
  return 0;
}
