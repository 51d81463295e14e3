// The GPU engine against the CPU, bit for bit, where a CUDA device is present (ctest -L gpu;
// bench/device-check.sh runs it on a lent machine). Without one each test says why it did not
// run and is reported skipped. The host side of a GPU run is tested everywhere, with the host in
// the GPU's place (tests/ensemble/test_device_lanes.cpp).
//
//   - the lane arithmetic the step is built from, on special and random operands: which
//     operation differs, where a realisation does;
//   - every realisation of every shipped ensemble (ensembles/*.toml), planar and 3D, on the GPU
//     and on the CPU engine (all cores): status, maxima, residuals, end time, spin, bit for bit;
//     and of the test ensembles with the Hunt-Crossley normal law;
//   - `caskdem ensemble --device auto` writes the CPU's result file.

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ensemble/device_runner.h"
#include "ensemble/ensemble_file.h"
#include "ensemble/plan.h"
#include "ensemble/runner.h"
#include "gpu/lane_arithmetic.h"
#include "io/hdf5_file.h"
#include "kernels/lane_device.h"
#include "support/command_line.h"
#include "support/result_files.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

// The first usable GPU, or null with the reason.
std::unique_ptr<LaneDevice> first_gpu(std::string* why) {
  const std::vector<CudaDeviceInfo> devices = cuda_devices(why);
  return devices.empty() ? nullptr : open_cuda_device(devices.front().ordinal);
}

std::uint64_t bits(double value) {
  std::uint64_t b = 0;
  std::memcpy(&b, &value, sizeof b);
  return b;
}

TEST(Gpu, LaneArithmeticGivesTheHostBits) {
  std::string why;
  if (!first_gpu(&why)) GTEST_SKIP() << "no GPU to compare with: " << why;
  // Special operands (signed zeros, NaN, infinities, subnormals, ties of nearbyint, the edges of
  // sin_cos's fast branch and of exp's clamp), each against each, then random ones over the
  // ranges the step uses.
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> special = {0.0,   -0.0,   1.0,  -1.0,   0.5,    -0.5,   1.5,   2.5,    -2.5,  0.75,
                                       -0.75, 0.7499, 40.0, 40.001, 1e-310, -1e-310, 1e300, -1e300, inf,   -inf,
                                       nan,   3.14159265358979, 1e5,   -7.0,   1023.4, -1021.6};
  std::vector<double> x, y;
  for (double a : special) {
    for (double b : special) {
      x.push_back(a);
      y.push_back(b);
    }
  }
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> angle(-10.0, 10.0), small(-1e-3, 1e-3), speed(0.0, 60.0);
  for (int i = 0; i < 200000; ++i) {
    const double a = i % 3 == 0 ? angle(random) : i % 3 == 1 ? small(random) : speed(random);
    x.push_back(a);
    y.push_back(angle(random));
  }
  const std::vector<double> host = testing::lane_arithmetic_on_host(x, y);
  std::vector<double> device;
  ASSERT_TRUE(testing::lane_arithmetic_on_device(x, y, device, &why)) << why;
  int differ[testing::kLaneResults] = {};
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (int r = 0; r < testing::kLaneResults; ++r) {
      const double h = host[i * testing::kLaneResults + r], d = device[i * testing::kLaneResults + r];
      if (bits(h) == bits(d)) continue;
      if (differ[r]++ < 3) {
        ADD_FAILURE() << testing::kLaneResultNames[r] << " for x = " << x[i] << ", y = " << y[i] << ": host " << h
                      << ", GPU " << d;
      }
    }
  }
  for (int r = 0; r < testing::kLaneResults; ++r) EXPECT_EQ(differ[r], 0) << testing::kLaneResultNames[r];
}

struct Fields {
  std::vector<std::uint64_t> values;
  bool operator==(const Fields&) const = default;
};

Fields fields_of(const RealisationOutcome& o) {
  Fields f;
  for (double v : {double(o.status), o.max_abs_rotation, o.max_abs_slide, o.residual_slide, o.max_uplift, o.impacts,
                   o.end_time, o.instability_time, o.spin, o.max_slip, o.residual_slip}) {
    f.values.push_back(bits(v));
  }
  return f;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Comparison {
  std::int64_t realisations = 0, identical = 0;
  double cpu_seconds = 0.0, gpu_seconds = 0.0;
};

// Every realisation of `spec` on the GPU and on the CPU engine (all cores), field by field.
Comparison gpu_against_cpu(LaneDevice& gpu, const EnsembleSpec& spec, const std::string& name) {
  const EnsemblePlan plan(spec, InstructionSet::automatic);
  const MotionTables tables(plan, MotionTables::kDeviceBudgetBytes);
  std::vector<std::int64_t> all(static_cast<std::size_t>(plan.size()));
  for (std::int64_t i = 0; i < plan.size(); ++i) all[static_cast<std::size_t>(i)] = i;
  std::vector<Fields> cpu(all.size()), device(all.size());
  std::vector<int> seen(all.size(), 0);
  RunOptions options;
  options.threads = omp_get_max_threads();
  options.lanes = spec.block_lanes;
  Comparison c;
  c.realisations = plan.size();
  auto start = std::chrono::steady_clock::now();
  run_realisations(plan, tables, all, options,
                   [&](const std::vector<std::int64_t>& done, const std::vector<RealisationOutcome>& outcomes) {
                     for (std::size_t k = 0; k < done.size(); ++k) cpu[done[k]] = fields_of(outcomes[k]);
                   });
  c.cpu_seconds = seconds_since(start);
  DeviceLanes lanes(plan, tables, gpu);
  options.device = &lanes;
  start = std::chrono::steady_clock::now();
  run_realisations(plan, tables, all, options,
                   [&](const std::vector<std::int64_t>& done, const std::vector<RealisationOutcome>& outcomes) {
                     for (std::size_t k = 0; k < done.size(); ++k) {
                       device[done[k]] = fields_of(outcomes[k]);
                       ++seen[done[k]];
                     }
                   });
  c.gpu_seconds = seconds_since(start);
  std::int64_t differ = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(seen[i], 1) << name << ": realisation " << i << " reported " << seen[i] << " times";
    if (device[i] == cpu[i]) {
      ++c.identical;
    } else if (++differ <= 3) {
      ADD_FAILURE() << name << ": realisation " << i << " differs";
    }
  }
  std::printf("%-40s %4d %12lld %12lld %10.2f %10.2f\n", name.c_str(), spec.three_d() ? 3 : 2,
              static_cast<long long>(c.realisations), static_cast<long long>(c.identical), c.cpu_seconds,
              c.gpu_seconds);
  std::fflush(stdout);
  return c;
}

TEST(Gpu, EveryShippedEnsembleGivesTheCpuBits) {
  std::string why;
  const std::unique_ptr<LaneDevice> gpu = first_gpu(&why);
  if (!gpu) GTEST_SKIP() << "no GPU to compare with: " << why;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(CASKDEM_SOURCE_DIR) + "/ensembles")) {
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
  std::printf("GPU: %s\n%-40s %4s %12s %12s %10s %10s\n", gpu->name().c_str(), "ensemble", "dim", "realisations",
              "identical", "CPU s", "GPU s");
  int planar = 0, spatial = 0;
  for (const std::filesystem::path& file : files) {
    const EnsembleSpec spec = load_ensemble(file);
    const Comparison c = gpu_against_cpu(*gpu, spec, file.filename().string());
    EXPECT_EQ(c.identical, c.realisations) << file.filename();
    (spec.three_d() ? spatial : planar) += 1;
  }
  EXPECT_GT(planar, 0);
  EXPECT_GT(spatial, 0);
}

// The Hunt-Crossley normal law with its damper (kernels/contact_law.h), planar and 3D.
TEST(Gpu, TheHuntCrossleyLawGivesTheCpuBits) {
  std::string why;
  const std::unique_ptr<LaneDevice> gpu = first_gpu(&why);
  if (!gpu) GTEST_SKIP() << "no GPU to compare with: " << why;
  for (const char* name : {"mixed-outcomes.toml", "mixed-outcomes-3d.toml"}) {
    EnsembleSpec spec = load_ensemble(std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/" + name);
    spec.base.model.normal_law = NormalLaw::hunt_crossley;
    spec.base.parameters.impact_damping = 2.0;  // s/m
    spec.uncertain.erase("restitution");
    const Comparison c = gpu_against_cpu(*gpu, spec, std::string(name) + " (Hunt-Crossley)");
    EXPECT_EQ(c.identical, c.realisations) << name;
  }
}

class GpuCommand : public testing::TemporaryFiles {};

TEST_F(GpuCommand, DeviceAutoWritesTheCpusResultFile) {
  std::string why;
  const std::unique_ptr<LaneDevice> gpu = first_gpu(&why);
  if (!gpu) GTEST_SKIP() << "no GPU to compare with: " << why;
  const std::string ensemble = std::string(CASKDEM_SOURCE_DIR) + "/ensembles/model-1-3-builtin.toml";
  const auto cpu = dir_ / "cpu.h5", automatic = dir_ / "auto.h5";
  const testing::Outcome on_cpu = testing::run_caskdem("ensemble " + ensemble + " --device cpu --no-plot --quiet --out " +
                                                       cpu.string());
  ASSERT_EQ(on_cpu.status, 0) << on_cpu.output;
  const testing::Outcome on_gpu = testing::run_caskdem("ensemble " + ensemble + " --device auto --no-plot --quiet --out " +
                                                       automatic.string());
  ASSERT_EQ(on_gpu.status, 0) << on_gpu.output;
  EXPECT_THAT(on_gpu.output, ::testing::HasSubstr("device          GPU "));
  testing::expect_same_results(cpu, automatic);
  EXPECT_EQ(hdf5::open_file(cpu).string_attribute("device"), "cpu");
  EXPECT_THAT(hdf5::open_file(automatic).string_attribute("device"), ::testing::HasSubstr("CUDA device"));
}

}  // namespace
}  // namespace caskdem
