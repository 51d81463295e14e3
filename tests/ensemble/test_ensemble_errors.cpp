// Bad ensemble files: one InputError that names the file, the line or key and what was
// expected.

#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.h"
#include "ensemble/ensemble_file.h"
#include "ensemble/plan.h"
#include "kernels/lane_device.h"
#include "support/command_line.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

// Variants of the mixed-outcomes ensemble, one line replaced.
class EnsembleErrors : public testing::TemporaryFiles {
 protected:
  std::filesystem::path variant(const std::string& name, const std::string& find, const std::string& replace) const {
    return variant_of(std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes.toml", name + ".toml",
                      find, replace);
  }
};

std::string error_of(const std::filesystem::path& file) {
  try {
    const EnsembleSpec spec = load_ensemble(file);
    const EnsemblePlan plan(spec, InstructionSet::automatic);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A motion's own factor or target would be undone by the scaling to each [intensity] level:
// refused at its key, not ignored.
TEST_F(EnsembleErrors, AMotionScaleOrTargetIsRefused) {
  for (const char* key : {"scale = 2", "target_pga = \"0.3 g\"", "target_pgv = \"20 cm/s\""}) {
    const std::string name = std::string(key).substr(0, std::string(key).find(' '));
    const auto file = variant(name, "cycles = 3\n", "cycles = 3\n" + std::string(key) + "\n");
    const std::string e = error_of(file);
    EXPECT_THAT(e, HasSubstr(file.string() + ":")) << key;
    EXPECT_THAT(e, HasSubstr("key motions[0]." + name)) << e;
    EXPECT_THAT(e, HasSubstr("expected no scale, target_pga or target_pgv")) << e;
  }
}

// Two limit states alike ("2 cm" and "20 mm") would collide in the result file after the run;
// they are refused when the file is read.
TEST_F(EnsembleErrors, ADuplicateThresholdIsRefusedBeforeTheRun) {
  const auto file = variant("duplicate", "sliding = [\"2 cm\"]", "sliding = [\"2 cm\", \"20 mm\"]");
  EXPECT_THAT(error_of(file), HasSubstr("key limit_states.sliding: the threshold sliding_0.02m is given twice; "
                                        "expected distinct thresholds"));
}

// A realisation is held to a case run's bounds (1e5 s, 1e10 steps) when the plan is made,
// before its peaks are sought, not found hours into the run: a contact stiffness a hundred
// times too high under a long sine train (a 20,000 s realisation of 1.2e10 steps).
TEST_F(EnsembleErrors, ARealisationLongerThanACaseRunMayBeIsRefused) {
  // At the paper's f_s = 0.01 (an ensemble's default step is five times longer).
  const auto paper_step = variant_of(variant("stiff", "cycles = 3\n", "cycles = 24000\n"), "stiff-paper-step.toml",
                                     "settle_time = \"1 s\"", "safety_factor = 0.01\nsettle_time = \"1 s\"");
  const auto stiff = variant_of(paper_step, "stiff-long.toml", "normal_stiffness = \"2.38e3 bar/cm\"",
                                "normal_stiffness = \"2.38e5 bar/cm\"");
  EXPECT_THAT(error_of(stiff), AllOf(HasSubstr("stiff-long.toml: motion motion 1: a realisation would last 20001 s in 1.1"),
                                     HasSubstr("expected at most 100000 s and 1e+10 steps")));
}

TEST_F(EnsembleErrors, UnknownDistribution) {
  const auto file = variant("weibull", "distribution = \"lognormal\"", "distribution = \"weibull\"");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr("key uncertain.friction_decay_speed.distribution"));
  EXPECT_THAT(e, HasSubstr("\"weibull\""));
  EXPECT_THAT(e, HasSubstr("expected one of"));
}

TEST_F(EnsembleErrors, NegativeBound) {
  const auto file = variant("negative", "low = 0.08", "low = -0.1");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr("key uncertain.friction_static.low"));
  EXPECT_THAT(e, HasSubstr("cannot be negative"));
}

TEST_F(EnsembleErrors, NanBound) {
  const auto file = variant("nan", "high = 0.8", "high = nan");
  EXPECT_THAT(error_of(file), HasSubstr("key uncertain.friction_static.high: expected a finite number"));
}

TEST_F(EnsembleErrors, EmptyStripeList) {
  const auto file = variant("no-stripes", "levels = [\"0.08 g\", \"0.4 g\", \"0.9 g\", \"1.6 g\"]", "levels = []");
  EXPECT_THAT(error_of(file), HasSubstr("key intensity.levels: expected a non-empty list"));
}

TEST_F(EnsembleErrors, ZeroRealisations) {
  const auto file = variant("zero", "realisations = 64", "realisations = 0");
  EXPECT_THAT(error_of(file), HasSubstr("key intensity.realisations: expected at least 1"));
}

TEST_F(EnsembleErrors, MoreRealisationsThanMemoryHolds) {
  const auto file = variant("billions", "realisations = 64", "realisations = 3000000000");
  EXPECT_THAT(error_of(file), HasSubstr("key intensity.realisations: expected at least 1 and at most 100000000"));
}

TEST_F(EnsembleErrors, LognormalSpreadBeyondAFactorOfTwenty) {
  // exp(500 z) overflows: once a late "decay speed must be positive" with no key.
  const auto file = variant("wide", "log_std = 0.5", "log_std = 500");
  EXPECT_THAT(error_of(file), HasSubstr("key uncertain.friction_decay_speed.log_std: expected a value between 0 and 3"));
}

TEST_F(EnsembleErrors, TruncationBoundsFarInATail) {
  // A normal 0.5 +- 0.001 cut to [0.94, 0.97] holds no probability; every draw was 0.94.
  const auto file = variant("tail", "distribution = \"uniform\"\nlow = 0.94\nhigh = 0.97",
                            "distribution = \"normal\"\nmean = 0.5\nstd = 0.001\nlow = 0.94\nhigh = 0.97");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr("key uncertain.restitution.low"));
  EXPECT_THAT(e, HasSubstr("hold a probability of 0"));
}

TEST_F(EnsembleErrors, CentreOfMassOutsideTheCask) {
  const auto file = variant("tall", "[intensity]",
                            "[uncertain.centre_height]\ndistribution = \"uniform\"\nlow = \"100 m\"\nhigh = \"200 m\"\n\n"
                            "[intensity]");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr("key uncertain.centre_height"));
  EXPECT_THAT(e, HasSubstr("must lie inside the cask"));
  EXPECT_THAT(e, HasSubstr("spans 100 to 200 m"));
}

TEST_F(EnsembleErrors, MissingRecord) {
  const auto file = variant("missing-record",
                            "kind = \"sine\"\namplitude = \"1 cm\"\nfrequency = \"1.2 Hz\"\ncycles = 3\nramp_cycles = 0.5",
                            "kind = \"record\"\nfile = \"no-such-record.AT2\"");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr("no-such-record.AT2"));
  EXPECT_THAT(e, HasSubstr("no such file"));
}

TEST_F(EnsembleErrors, RestitutionOutOfTheCasksReach) {
  const auto file = variant("restitution", "high = 0.97", "high = 0.995");
  const std::string e = error_of(file);
  EXPECT_THAT(e, HasSubstr("key uncertain.restitution"));
  EXPECT_THAT(e, HasSubstr("reaches restitutions"));
}

// [run] device takes auto, cpu or cuda, named at its line otherwise.
TEST_F(EnsembleErrors, UnknownDevice) {
  const auto file = variant("device", "[uncertain.friction_static]", "[run]\ndevice = \"gpu\"\n\n[uncertain.friction_static]");
  EXPECT_THAT(error_of(file), AllOf(HasSubstr(file.string() + ":"), HasSubstr("key run.device"),
                                    HasSubstr("auto"), HasSubstr("cuda")));
}

// A GPU asked for on a machine or build without one: one line with the reason, exit status 2,
// before any work; from the option and from the file's key alike. `auto` runs on the CPU.
TEST_F(EnsembleErrors, CudaWithoutAGpuIsRefusedWithItsReason) {
  std::string why;
  if (!cuda_devices(&why).empty()) GTEST_SKIP() << "this machine has a GPU";
  const auto small = variant("small", "realisations = 64", "realisations = 2");
  const auto out = dir_ / "out.h5";
  const testing::Outcome option =
      testing::run_caskdem("ensemble " + small.string() + " --device cuda --no-plot --out " + out.string());
  EXPECT_EQ(option.status, 2) << option.output;
  EXPECT_THAT(option.output, HasSubstr("--device cuda: no GPU to run on: " + why + "; expected auto or cpu"));
  EXPECT_FALSE(std::filesystem::exists(out));
  const auto keyed = variant("keyed", "[uncertain.friction_static]", "[run]\ndevice = \"cuda\"\n\n[uncertain.friction_static]");
  const testing::Outcome file = testing::run_caskdem("ensemble " + keyed.string() + " --no-plot --out " + out.string());
  EXPECT_EQ(file.status, 2) << file.output;
  EXPECT_THAT(file.output, AllOf(HasSubstr(keyed.string() + ":"), HasSubstr("[run] device: no GPU to run on")));
  const testing::Outcome automatic =
      testing::run_caskdem("ensemble " + small.string() + " --device auto --no-plot --quiet --out " + out.string());
  EXPECT_EQ(automatic.status, 0) << automatic.output;
  EXPECT_THAT(automatic.output, HasSubstr("device          CPU, "));
}

TEST_F(EnsembleErrors, UnknownParameter) {
  const auto file = variant("unknown", "[uncertain.friction_static]", "[uncertain.friction_statc]");
  EXPECT_THAT(error_of(file), HasSubstr("unknown key uncertain.friction_statc"));
}

}  // namespace
}  // namespace caskdem
