#pragma once
// The components of one station's record read as one motion: two horizontals (H1, H2) and
// optionally the vertical, on one time base. PEER distributes each component in a file of its
// own (.AT2); the components of a set share the time step and start together at t = 0, and
// where their lengths differ only the tails do (../shared/motions/three-component/README.md).
// A set is read as it comes: the components must agree on the time step (within 1e-6
// relative, as a record's own samples must); different lengths are trimmed to the shortest
// (the default) or padded with zeros to the longest, and the set says which.

#include <filesystem>
#include <optional>
#include <string>

#include "motion/record.h"

namespace caskdem::motion {

enum class TailRule { trim, pad };

struct ComponentSet {
  Record h1, h2;                   // the horizontal pair, same time step and length
  std::optional<Record> vertical;  // same time step and length when present
  // What putting the components on one time base did, for the output: "" when they already
  // shared it, else e.g. "lengths 5372, 5346, 5378 samples: trimmed to 5346 (53.45 s)".
  std::string time_base;
};

// Reads each file with `options` (a unit or format given applies to every component). An
// InputError names the file and line of a component that cannot be read, or both files whose
// time steps differ.
ComponentSet read_component_set(const std::filesystem::path& h1, const std::filesystem::path& h2,
                                const std::optional<std::filesystem::path>& vertical, const ReadOptions& options = {},
                                TailRule tails = TailRule::trim);

}  // namespace caskdem::motion
