#pragma once
// The answer of an ensemble as files: the /limit_states group of the result file, and beside the
// result file a fragility table for Python and spreadsheets (docs/output.md):
//
//   NAME-fragility.json   per limit state: the curve (median in the user's unit and at full size
//                         for a 1/N model, log-std), its test with the motions clustered and the
//                         binomial one, "rejected", the record-to-record share, the curve under the
//                         other measures, the casks that exceeded while standing, and per stripe
//                         the runs, exceedances and interval
//   NAME-fragility.csv    one row per limit state and stripe, the curve's numbers repeated on each
//                         row, a header of column names with their units (pandas and numpy read
//                         it with their defaults)
//
// HDF5 keeps SI with a `units` attribute on every numeric dataset; the JSON and CSV give
// intensities in the unit users read (g, cm/s), stated once at the top of the JSON and in the
// CSV's column names.

#include <filesystem>
#include <vector>

#include "ensemble/analysis.h"
#include "ensemble/plan.h"
#include "io/hdf5_file.h"

namespace caskdem {

// The SI unit of the ensemble's measure ("m/s", "m/s^2", "1" for the ratios).
std::string intensity_si_unit(IntensityMeasure measure);

void write_limit_states(hdf5::Group& root, const EnsemblePlan& plan, const std::vector<LimitStateSummary>& summaries);

// NAME-fragility.json and NAME-fragility.csv beside `result_file` (NAME.h5); returns their paths.
std::vector<std::filesystem::path> write_fragility_tables(const std::filesystem::path& result_file,
                                                          const EnsemblePlan& plan,
                                                          const std::vector<LimitStateSummary>& summaries);

}  // namespace caskdem
