#pragma once
// An earlier diagnosis of the same cask as starts for this one's searches
// (`caskdem diagnose DIR --start-from EARLIER/diagnosis.json`).
//
// A laboratory that runs the proposed test diagnoses the set again with that test added. Each fit
// explores its box afresh and the objective of rocking tests is a field of narrow basins, so
// the second search can end in another basin than the first found, one that fits the new
// tests worse than the first fit's point does (docs/diagnosis-accuracy.md, "The loop closed":
// the worked example's convex base, refitted with its proposed test, ended with the stiffness
// scale at its bound and a training J of 161.9 where the truth's is 152.9). Here every fit of
// the earlier file whose model and form (footprint rule and normal law) match a fit of this
// diagnosis is evaluated in that fit's first population and searched from, beside the searches
// its exploration chooses, which stay as they would be without it (fitting.h, searched_also): the
// fit ends no higher than the earlier point's J on the present tests nor than the fit made
// without it, and where the earlier point's search does not end lowest it is that fit.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "diagnosis/measured_set.h"
#include "diagnosis/mechanisms.h"

namespace caskdem::diagnosis {

struct EarlierFit {
  std::string footprint;   // footprint_name, "" for a section that is not a cylinder
  std::string normal_law;  // normal_law_name
  std::string model;       // ModelVariant::name(): "baseline" or "baseline + a + b"
  std::vector<std::pair<std::string, double>> values;  // parameter name, physical value
};

struct EarlierFits {
  std::filesystem::path source;
  std::vector<EarlierFit> fits;
};

// Every fit in a diagnosis.json (the baseline, each model form's baseline, each mechanism's and
// pair's fit, the cause refitted) or the one fit of a calibration.json, each checked against
// the parameters its model has on `set`'s specimen. An InputError naming the file and the key
// for a file that is not such a result.
EarlierFits read_earlier_fits(const std::filesystem::path& file, const MeasuredSet& set);

// The starts the earlier fits give a fit of `variant` on `specimen`'s form: the values of each
// earlier fit of the same model and form, in the variant's parameter order, each moved into its
// search box (a box that depends on the specimen may have changed). Distinct, in file order.
std::vector<std::vector<double>> earlier_starts(const EarlierFits& earlier, const Case& specimen,
                                                const ModelVariant& variant);

}  // namespace caskdem::diagnosis
