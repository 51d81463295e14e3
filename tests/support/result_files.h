#pragma once
// Two ensemble result files hold the same results: every dataset of /realisations, /stripes and
// each /limit_states group, bit for bit, and each fit's attributes. The run's own attributes
// (wall time, device, instruction set, threads) may differ.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "io/hdf5_file.h"

namespace caskdem::testing {

// The bit patterns of a dataset's numbers (integers and bytes read as doubles, which is exact
// for the counts and flags these files hold), so that -0 and +0, or two NaNs, are told apart.
inline std::vector<std::uint64_t> dataset_bits(const hdf5::Group& group, const std::string& name) {
  const std::vector<double> values = group.read_doubles(name);
  std::vector<std::uint64_t> bits(values.size());
  if (!values.empty()) std::memcpy(bits.data(), values.data(), values.size() * sizeof(double));
  return bits;
}

inline bool is_group(const hdf5::Group& parent, const std::string& name) {
  try {
    parent.open_group(name);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

inline void expect_same_datasets(const hdf5::Group& a, const hdf5::Group& b, const std::string& where) {
  const std::vector<std::string> names = a.member_names();
  EXPECT_EQ(names, b.member_names()) << where;
  for (const std::string& name : names) {
    if (!b.has(name)) continue;
    if (is_group(a, name)) {
      expect_same_datasets(a.open_group(name), b.open_group(name), where + "/" + name);
      continue;
    }
    if (name == "name") continue;  // strings (motion names), from the same plan
    EXPECT_EQ(dataset_bits(a, name), dataset_bits(b, name)) << where << "/" << name;
  }
}

inline void expect_same_results(const std::filesystem::path& first, const std::filesystem::path& second) {
  const hdf5::Group a = hdf5::open_file(first);
  const hdf5::Group b = hdf5::open_file(second);
  EXPECT_EQ(a.integer_attribute("completed"), b.integer_attribute("completed"));
  expect_same_datasets(a.open_group("realisations"), b.open_group("realisations"), "realisations");
  ASSERT_EQ(a.has("limit_states"), b.has("limit_states"));
  if (!a.has("limit_states")) return;
  const hdf5::Group la = a.open_group("limit_states"), lb = b.open_group("limit_states");
  expect_same_datasets(la, lb, "limit_states");
  for (const std::string& state : la.member_names()) {
    const hdf5::Group sa = la.open_group(state), sb = lb.open_group(state);
    EXPECT_EQ(sa.integer_attribute("fitted"), sb.integer_attribute("fitted")) << state;
    if (!sa.integer_attribute("fitted")) continue;
    for (const char* fit : {"median", "log_std"}) {
      const double x = sa.double_attribute(fit), y = sb.double_attribute(fit);
      EXPECT_EQ(std::memcmp(&x, &y, sizeof x), 0) << state << " " << fit << ": " << x << " and " << y;
    }
  }
}

}  // namespace caskdem::testing
