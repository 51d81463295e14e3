// The command line on bad input: one clear message on stderr naming the file and the line
// or key, and a non-zero exit; on good input, the promised files.

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "kernels/block.h"
#include "support/command_line.h"
#include "support/paper_cases.h"
#include "support/temporary_files.h"

namespace caskdem {
namespace {

using ::testing::HasSubstr;

using testing::Outcome;
using testing::run_caskdem;
using CommandLine = testing::TemporaryFiles;

TEST_F(CommandLine, MissingCaseFile) {
  const Outcome o = run_caskdem("run /nonexistent/case.toml");
  EXPECT_NE(o.status, 0);
  EXPECT_THAT(o.output, HasSubstr("/nonexistent/case.toml: no such file"));
}

// A device or a FIFO given where a file is read is refused before it is opened, by every
// command: `caskdem motion /dev/zero` read without end, and opening a FIFO waits for a writer.
// `timeout` turns a hang into a failure here rather than a stalled test run.
TEST_F(CommandLine, ADeviceOrAFifoIsRefusedByEveryCommandBeforeReading) {
  const std::filesystem::path fifo = dir_ / "input.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::filesystem::path measured = dir_ / "measured";
  std::filesystem::create_directories(measured);
  ASSERT_EQ(::mkfifo((measured / "specimen.toml").c_str(), 0600), 0);
  const std::string out = (dir_ / "out").string();
  struct Case {
    std::string arguments, file;
  };
  const std::vector<Case> cases = {
      {"motion /dev/zero --unit g", "/dev/zero"},
      {"motion " + fifo.string() + " --unit g", fifo.string()},
      {"run /dev/zero --out " + out, "/dev/zero"},
      {"run " + fifo.string() + " --out " + out, fifo.string()},
      {"ensemble /dev/zero --out " + out + ".h5", "/dev/zero"},
      {"plot /dev/zero", "/dev/zero"},
      {"diagnose " + measured.string() + " --out " + out, (measured / "specimen.toml").string()},
  };
  for (const Case& c : cases) {
    const Outcome o = testing::run_shell("timeout 60 " + std::string(CASKDEM_BINARY) + " " + c.arguments);
    EXPECT_EQ(o.status, 2) << c.arguments << ": " << o.output;
    EXPECT_THAT(o.output, HasSubstr(c.file + ": is not a regular file")) << c.arguments;
    EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << "one message: " << o.output;
  }
}

TEST_F(CommandLine, MalformedRecordLineNamesFileAndLine) {
  const auto record = write("bad-record.csv", "t,a\n0.00,0.01\n0.01,0.02\n0.02,abc\n0.03,0.01\n");
  const Outcome o = run_caskdem("motion " + record.string() + " --unit g");
  EXPECT_EQ(o.status, 2);
  EXPECT_THAT(o.output, HasSubstr(record.string() + ":4"));
  EXPECT_THAT(o.output, HasSubstr("expected"));
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << "one message: " << o.output;
}

// A record without motion has no factor that brings it to a target: the file and the option
// that asked are named, once.
TEST_F(CommandLine, AZeroRecordCannotBeScaledToATarget) {
  const auto record = write("still.csv", "t,a\n0.00,0\n0.01,0\n0.02,0\n0.03,0\n");
  for (const char* option : {"--target-pga 300", "--target-pgv 20"}) {
    const Outcome o = run_caskdem("motion " + record.string() + " --unit g " + option);
    EXPECT_EQ(o.status, 2) << option;
    EXPECT_THAT(o.output, HasSubstr(record.string() + ": the record's accelerations are all zero")) << option;
    EXPECT_THAT(o.output, HasSubstr(std::string("(asked for by ") + std::string(option).substr(0, 12) + ")"));
    EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << "one message: " << o.output;
  }
}

// A station's components: reported on one time base, with the pair's measures; components of
// different stations (time steps that differ) and a target for a pair are refused, once.
TEST_F(CommandLine, AStationsComponentsAreReportedTogetherOrRefused) {
  const std::string sets = std::string(CASKDEM_SHARED_DIR) + "/motions/three-component/";
  const std::string h1 = sets + "elcentro1940_RSN6_H1_180.AT2", h2 = sets + "elcentro1940_RSN6_H2_270.AT2";
  const Outcome o = run_caskdem("motion " + h1 + " --pair " + h2 + " --vertical " + sets + "elcentro1940_RSN6_UP.AT2");
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_THAT(o.output, HasSubstr("lengths 5372, 5346, 5378 samples: trimmed to 5346"));
  EXPECT_THAT(o.output, HasSubstr("H1         0.2808 g"));
  EXPECT_THAT(o.output, HasSubstr("RotD50"));
  const std::string kobe = sets + "kobe1995_RSN1106_KJMA_H2_090.AT2";
  for (const auto& [arguments, message] :
       {std::pair{"motion " + h1 + " --pair " + kobe, kobe + ": time step 0.02 s, but " + h1 + " has 0.01 s"},
        std::pair{"motion " + h1 + " --pair " + h2 + " --target-pga 300",
                  std::string("--target-pga: a station's components are scaled together")}}) {
    const Outcome refused = run_caskdem(arguments);
    EXPECT_EQ(refused.status, 2) << arguments << ": " << refused.output;
    EXPECT_THAT(refused.output, HasSubstr(message)) << arguments;
    EXPECT_EQ(std::count(refused.output.begin(), refused.output.end(), '\n'), 1) << "one message: " << refused.output;
  }
}

// A 3D case runs the station's three components as one motion: scaled together so that the
// pair's RotD50 PGA is the target, trimmed to one time base (and saying so), and writes the
// summary, the histories (CSV, HDF5) and the plot.
TEST_F(CommandLine, AThreeDimensionalCaseRunsTheStationsComponentsTogether) {
  const std::string sets = std::string(CASKDEM_SHARED_DIR) + "/motions/three-component/";
  const auto file = write("elcentro-3d.toml", R"(title = "3D El Centro"
[cask]
shape = "cylinder"
dimensions = 3
diameter = "0.95 m"
height = "2.033 m"
density = "8.743 g/cm^3"
[contact]
normal_stiffness = "2.38e3 bar/cm"
shear_stiffness = "2.21e3 bar/cm"
[friction]
law = "constant"
coefficient = 0.6
[damping]
ratio = 0.056
[integration]
duration = "6 s"
[output]
interval = "0.01 s"
[motion]
kind = "record"
file = ")" + sets + R"(elcentro1940_RSN6_H1_180.AT2"
pair = ")" + sets + R"(elcentro1940_RSN6_H2_270.AT2"
vertical_file = ")" + sets + R"(elcentro1940_RSN6_UP.AT2"
target_pga = "500 gal"
incidence = "30 deg"
similarity_scale = 3
)");
  const std::filesystem::path out = dir_ / "out";
  const Outcome o = run_caskdem("run " + file.string() + " --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_THAT(o.output, HasSubstr("(3D)"));
  EXPECT_THAT(o.output, HasSubstr("incidence 30 deg"));
  EXPECT_THAT(o.output, HasSubstr("lengths 5372, 5346, 5378 samples: trimmed to 5346"));
  for (const char* name : {"summary.json", "history.csv", "run.h5", "history.png"}) {
    EXPECT_TRUE(std::filesystem::exists(out / name)) << name;
  }
  const std::string summary = testing::file_text(out / "summary.json");
  EXPECT_THAT(summary, HasSubstr("\"dimensions\": 3"));
  const std::smatch rotd50 = [&] {
    std::smatch m;
    std::regex_search(summary, m, std::regex("\"pga_rotd50_m_s2\": ([0-9.eE+-]+)"));
    return m;
  }();
  ASSERT_FALSE(rotd50.empty()) << summary;
  EXPECT_NEAR(std::stod(rotd50[1].str()), 5.0, 1e-9) << "the pair as applied has the target RotD50";
  std::ifstream csv(out / "history.csv");
  std::string header, line;
  std::getline(csv, header);  // the first line: no comment before it (pandas and numpy read it as the header)
  EXPECT_EQ(header.rfind("time_s,tilt_rad,tilt_azimuth_rad,spin_rad,rim_contact_azimuth_rad,slide_x_m,slide_z_m", 0), 0u)
      << header;
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 600) << "6 s sampled every 0.01 s (whole steps) from t = 0, as a planar run is";

  // The commands that run the planar model refuse a 3D cask rather than run it flat; an
  // ensemble takes one but not the planar base's keys; --motion cannot stand in for a whole set.
  const auto ensemble = variant_of(std::string(CASKDEM_SOURCE_DIR) + "/ensembles/model-1-3-builtin.toml",
                                   "ensemble-3d.toml", "shape = \"cylinder\"", "shape = \"cylinder\"\ndimensions = 3");
  for (const auto& [arguments, message] :
       {std::pair{"calibrate " + file.string(), std::string("`calibrate` runs the planar model")},
        std::pair{"sweep " + file.string() + " --out " + (dir_ / "s").string(), std::string("`sweep` runs the planar model")},
        std::pair{"ensemble " + ensemble.string() + " --out " + (dir_ / "e.h5").string(),
                  std::string("key cask.half_width: a 3D cask stands on its whole circular base")},
        std::pair{"run " + file.string() + " --motion " + sets + "elcentro1940_RSN6_H1_180.AT2",
                  std::string("--motion replaces one record, and this case's motion is a station's set")}}) {
    const Outcome refused = run_caskdem(arguments);
    EXPECT_EQ(refused.status, 2) << arguments << ": " << refused.output;
    EXPECT_THAT(refused.output, HasSubstr(message)) << arguments;
  }
}

// A record sample no earthquake can produce (mutation fuzzing found 5.4e305 g accepted and
// printed as "inf gal") is refused with the file, the line and the value; so is a scaling
// beyond the largest acceleration, and a similarity scale whose ratios overflow. Nothing
// prints inf or nan.
TEST_F(CommandLine, AnImpossibleRecordValueOrScalingIsRefused) {
  const auto huge = write("huge.csv", "t,a\n0.00,0.01\n0.01,5.4e305\n0.02,0.02\n");
  const Outcome o = run_caskdem("motion " + huge.string() + " --unit g");
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_THAT(o.output, HasSubstr(huge.string() + ":3: found '5.4e305'"));
  EXPECT_THAT(o.output, HasSubstr("expected accelerations of at most 1000 m/s^2 (about 100 g)"));
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << "one message: " << o.output;

  const auto record = write("one-g.csv", "t,a\n0.00,0\n0.01,1\n0.02,-1\n0.03,0\n");
  const auto still = write("almost-still.csv", "t,a\n0.00,0\n0.01,5e-324\n0.02,0\n");
  for (const std::string& arguments : {"motion " + record.string() + " --unit g --scale 200",
                                       "motion " + record.string() + " --unit g --target-pga 2e5",
                                       "motion " + record.string() + " --unit g --target-pgv 1e9",
                                       "motion " + still.string() + " --unit m/s^2 --target-pga 100",
                                       std::string("similarity 1e-300")}) {
    const Outcome scaled = run_caskdem(arguments);
    EXPECT_EQ(scaled.status, 2) << arguments << "\n" << scaled.output;
    EXPECT_THAT(scaled.output, ::testing::Not(HasSubstr("inf"))) << arguments;
    EXPECT_THAT(scaled.output, ::testing::Not(HasSubstr("nan"))) << arguments;
    EXPECT_EQ(std::count(scaled.output.begin(), scaled.output.end(), '\n'), 1) << arguments << "\n" << scaled.output;
  }
}

// Values in the wrong unit that passed every key's own check: a density a thousand orders of
// magnitude off ran one step of 6e144 s and reported "completed"; a pulse of 1e308 g stopped
// with a library message naming neither file nor key.
TEST_F(CommandLine, ValuesInTheWrongUnitAreRefusedBeforeTheRun) {
  struct Case {
    std::string from, to, message;
  };
  for (const Case& c : std::vector<Case>{
           {"density = \"8.743 g/cm^3\"", "density = \"1e300 g/cm^3\"", "expected 1 to 1e+10"},
           {"amplitude = \"0.35 g\"", "amplitude = \"1e308 g\"", "key motion.amplitude: expected a non-zero acceleration of at most 1000 m/s^2"},
       }) {
    const auto file = variant_of(testing::case_path("default-pulse.toml"), "wrong-unit.toml", c.from, c.to);
    const Outcome o = run_caskdem("run " + file.string() + " --out " + (dir_ / "never").string());
    EXPECT_EQ(o.status, 2) << c.to << "\n" << o.output;
    EXPECT_THAT(o.output, HasSubstr(file.filename().string())) << c.to;
    EXPECT_THAT(o.output, HasSubstr(c.message)) << c.to;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "never" / "summary.json")) << c.to;
  }
}

TEST_F(CommandLine, BadCaseValueExitsNonZeroWithOneMessage) {
  const auto file = variant_of(testing::case_path("model-1-3-sine.toml"), "bad-case.toml", "kinetic = 0.45",
                               "kinetic = \"lots\"");
  const Outcome o = run_caskdem("run " + file.string() + " --out " + (dir_ / "out").string());
  EXPECT_EQ(o.status, 2);
  EXPECT_THAT(o.output, HasSubstr("key friction.kinetic: expected a number"));
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << o.output;
}

// The plotting interpreter gets its paths as arguments, not through a shell: a quote or a
// `$(...)` in the output path neither breaks the plot nor runs a command.
TEST_F(CommandLine, APathWithAQuoteOrACommandIsPlottedAsItIs) {
  const auto out = dir_ / "it's $(touch injected)";
  std::string quoted = "'";  // for the test's own shell: ' becomes '\''
  for (char c : out.string()) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  quoted += "'";
  const Outcome o = testing::run_shell("cd '" + dir_.string() + "' && " + std::string(CASKDEM_BINARY) + " run " +
                                       testing::case_path("default-pulse.toml") + " --out " + quoted);
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_TRUE(std::filesystem::exists(out / "history.png"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "injected"));
}

TEST_F(CommandLine, RunWritesSummaryHistoryHdf5AndPlot) {
  const auto out = dir_ / "out";
  const Outcome o = run_caskdem("run " + testing::case_path("default-pulse.toml") + " --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_THAT(o.output, HasSubstr("max |theta|"));
  for (const char* name : {"summary.json", "history.csv", "run.h5", "history.png"}) {
    EXPECT_TRUE(std::filesystem::exists(out / name)) << name;
    EXPECT_GT(std::filesystem::file_size(out / name), 100u) << name;
  }
  // docs/output.md promises h5py-readable output: read it back with Debian's python.
  const Outcome read = run_caskdem("--version");
  EXPECT_EQ(read.status, 0);
  const std::string check = "/usr/bin/python3 -c \"import h5py; f = h5py.File('" + (out / "run.h5").string() +
                            "'); print(len(f['history/time']), f['summary'].attrs['status'])\"";
  const Outcome h5py = testing::run_shell(check);
  EXPECT_EQ(h5py.status, 0) << h5py.output;
  EXPECT_THAT(h5py.output, HasSubstr("completed"));
}

TEST_F(CommandLine, NoNanInResultFiles) {
  const auto out = dir_ / "out";
  ASSERT_EQ(run_caskdem("run " + testing::case_path("default-pulse.toml") + " --no-plot --out " + out.string()).status, 0);
  for (const char* name : {"summary.json", "history.csv"}) {
    const std::string text = testing::file_text(out / name);
    EXPECT_EQ(text.find("nan"), std::string::npos) << name;
    EXPECT_EQ(text.find("inf"), std::string::npos) << name;
  }
}

// A command line that does not parse is bad input too: status 2, one message naming the
// option and what it expects (CLI11's own statuses are 100 and up).
TEST_F(CommandLine, BadOptionValuesExitTwoNamingTheOption) {
  struct Case {
    std::string arguments, message;
  };
  const std::string out = (dir_ / "never").string();
  for (const Case& c : std::vector<Case>{
           // libgomp crashed creating 100000 threads.
           {"ensemble none.toml --threads 100000", "--threads: expected a whole number of threads from 0 (all cores) to 1024"},
           {"ensemble none.toml --threads abc", "--threads: expected a whole number of threads"},
           // CLI11 wrapped -3 to 2^64 - 3.
           {"synthesize-measured --out " + out + " --seed -3", "--seed: expected a seed, a whole number"},
           {"synthesize-measured --out " + out + " --table-noise 1e300", "--table-noise: expected a table noise"},
           {"synthesize-measured --out " + out + " --drive d.csv --test 0", "--test: expected a test number"},
           {"synthesize-measured --out " + out + " --drive d.csv", "--drive requires --test"},
           // The loop closed on a set that is not there: its truth.json is named.
           {"synthesize-measured --out " + out + " --drive d.csv --test 9", "truth.json: cannot be read"},
           // An added test has the set's noise levels.
           {"synthesize-measured --out " + out + " --drive d.csv --test 9 --slide-noise 0", "--slide-noise excludes --drive"},
           // Ignored before: the record was printed unscaled.
           {"motion none.csv --scale -1", "--scale: expected a finite number above zero"},
           {"motion none.csv --target-pga nan", "--target-pga: expected a finite number above zero"},
           {"calibrate none.toml --target nan", "--target: expected a restitution from 0.01 to 0.9999"},
           {"similarity 0", "scale: expected a finite number above zero, got \"0\""},
           // Both aborted the program, the first in the parallel loop, the second after hours.
           {"sweep " + testing::case_path("model-1-3-sine.toml") + " --out " + out + " --cycles 3",
            "--ramp-cycles 2: expected at most half of --cycles (3)"},
           {"sweep " + testing::case_path("model-1-3-sine.toml") + " --out " + out + " --cycles 1e9",
            "--cycles 1e+09: expected at most 100000 s of shaking"},
           {"run", "case is required"},
       }) {
    const Outcome o = run_caskdem(c.arguments);
    EXPECT_EQ(o.status, 2) << c.arguments << "\n" << o.output;
    EXPECT_THAT(o.output, HasSubstr(c.message)) << c.arguments;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.arguments;
  }
  EXPECT_EQ(run_caskdem("--help").status, 0);
}

// Where results cannot go is said before the work, not after it as a filesystem error.
TEST_F(CommandLine, AnUnusableOutputPathIsRefusedFirst) {
  const auto file = write("taken", "a file, not a directory\n");
  const Outcome run = run_caskdem("run " + testing::case_path("default-pulse.toml") + " --out " + file.string());
  EXPECT_EQ(run.status, 2);
  EXPECT_THAT(run.output, HasSubstr(file.string() + ": is a file; expected a directory for the results"));
  EXPECT_THAT(run.output, ::testing::Not(HasSubstr("max |theta|"))) << "refused before running";

  const Outcome synthesize = run_caskdem("synthesize-measured --out " + file.string());
  EXPECT_EQ(synthesize.status, 2);
  EXPECT_THAT(synthesize.output, HasSubstr("is a file"));

  const Outcome ensemble = run_caskdem("ensemble " + std::string(CASKDEM_SOURCE_DIR) +
                                       "/tests/ensemble/data/mixed-outcomes.toml --out " + dir_.string());
  EXPECT_EQ(ensemble.status, 2);
  EXPECT_THAT(ensemble.output, HasSubstr(dir_.string() + ": is a directory; expected a file name for the results"));
}

// An instruction set the machine lacks is refused before any work, naming the option; one it
// has runs. (On a machine with AVX-512 only the second half can be seen.)
TEST_F(CommandLine, AnInstructionSetTheMachineLacksIsRefusedFirst) {
  const std::string ensemble = std::string(CASKDEM_SOURCE_DIR) + "/tests/ensemble/data/mixed-outcomes.toml";
  for (const InstructionSet isa : {InstructionSet::avx512f, InstructionSet::avx2, InstructionSet::sse2}) {
    const auto out = dir_ / (instruction_set_name(isa) + ".h5");
    const Outcome o = run_caskdem("ensemble " + ensemble + " --isa " + instruction_set_name(isa) + " --out " +
                                  out.string() + " --quiet --no-plot --threads 1");
    if (instruction_set_available(isa)) {
      EXPECT_EQ(o.status, 0) << o.output;
    } else {
      EXPECT_EQ(o.status, 2) << o.output;
      EXPECT_THAT(o.output, HasSubstr("--isa: " + instruction_set_name(isa) + " is not available on this machine"));
      EXPECT_FALSE(std::filesystem::exists(out));
    }
  }
}

TEST_F(CommandLine, PlottingAFileThatIsNotAnEnsembleResultSaysSo) {
  const auto text = write("notes.h5", "not HDF5\n");
  const Outcome o = run_caskdem("plot " + text.string());
  EXPECT_EQ(o.status, 2);
  EXPECT_THAT(o.output, HasSubstr("notes.h5"));
  EXPECT_THAT(o.output, HasSubstr("expected a result file of caskdem ensemble"));
  EXPECT_THAT(o.output, ::testing::Not(HasSubstr("Traceback")));
}

// The README's promise, command by command: bad input ends with one line naming the file and
// the line or key (or the option) and what was expected, status 2, and nothing written. The
// commands are read from `caskdem --help`, so a new command without a case here fails.
TEST_F(CommandLine, EveryCommandRefusesBadInputWithOneLineAndStatusTwo) {
  const std::string source = CASKDEM_SOURCE_DIR;
  const std::string bad_case = testing::file_text(source + "/cases/default-pulse.toml");
  const auto case_file = write("case.toml", std::regex_replace(bad_case, std::regex("rounding = \"0.5 cm\""),
                                                                "rounding = \"0.5 kg\""));
  const std::string bad_line = ":11: key cask.rounding: unit \"kg\" is not a length unit";
  const auto record = write("record.csv", "t, a\n0.00, 0.1\n0.01, x\n");
  const std::string ensemble_text = testing::file_text(source + "/tests/ensemble/data/mixed-outcomes.toml");
  const auto ensemble = write("ensemble.toml", std::regex_replace(ensemble_text, std::regex("settle_time = \"1 s\""),
                                                                  "settle_time = \"1 kg\""));
  const auto not_a_result = write("result.h5", "not HDF5\n");
  const std::filesystem::path measured = dir_ / "measured";
  ASSERT_EQ(run_caskdem("synthesize-measured --out " + measured.string()).status, 0);
  const std::string specimen = testing::file_text(measured / "specimen.toml");
  ASSERT_NE(specimen.find("starts = 6"), std::string::npos);
  std::ofstream(measured / "specimen.toml") << std::regex_replace(specimen, std::regex("starts = 6"), "starts = six");
  const auto bad_json = write("diagnosis.json", "{\"cause\": ");
  const auto hazard = write("hazard.csv", "PGA [g], annual frequency\n0.1, 1e-3\n0.2, 2e-3\n");
  const std::filesystem::path good = dir_ / "good";
  ASSERT_EQ(run_caskdem("synthesize-measured --out " + good.string()).status, 0);

  const std::string out = (dir_ / "out").string();
  struct Case {
    std::string arguments, message;
  };
  const std::map<std::string, Case> cases = {
      {"run", {"run " + case_file.string() + " --out " + out, case_file.string() + bad_line}},
      {"calibrate", {"calibrate " + case_file.string(), case_file.string() + bad_line}},
      {"sweep", {"sweep " + case_file.string() + " --out " + out, case_file.string() + bad_line}},
      {"motion", {"motion " + record.string() + " --unit g", record.string() + ":3: found 'x'"}},
      {"similarity", {"similarity abc", "scale: expected a finite number above zero, got \"abc\""}},
      {"ensemble", {"ensemble " + ensemble.string() + " --out " + out, ensemble.string() + ":28: key integration.settle_time"}},
      {"plot", {"plot " + not_a_result.string(), not_a_result.string() + ": has no caskdem seal"}},
      {"calibrate-measured",
       {"calibrate-measured " + measured.string() + " --out " + out, (measured / "specimen.toml").string() + ":30:"}},
      {"diagnose", {"diagnose " + measured.string() + " --out " + out, (measured / "specimen.toml").string() + ":30:"}},
      {"evaluate-measured",
       {"evaluate-measured " + good.string() + " --from " + bad_json.string() + " --json " + out, bad_json.string()}},
      {"plan-test", {"plan-test " + good.string() + " --from " + bad_json.string() + " --out " + out, bad_json.string()}},
      {"synthesize-measured", {"synthesize-measured --out " + out + " --effect nonsense", "--effect: unknown mechanism \"nonsense\""}},
      {"risk", {"risk --hazard " + hazard.string() + " --median \"0.9 g\" --beta 0.4 --json " + out,
                hazard.string() + ":3: the hazard rises from 0.001 to 0.002 per year"}},
  };

  const Outcome help = run_caskdem("--help");
  ASSERT_EQ(help.status, 0);
  std::istringstream lines(help.output.substr(help.output.find("Subcommands:")));
  std::string line;
  std::getline(lines, line);
  int commands = 0;
  while (std::getline(lines, line)) {
    std::smatch command;
    if (!std::regex_search(line, command, std::regex("^  ([a-z-]+) "))) continue;
    ++commands;
    const auto c = cases.find(command[1]);
    ASSERT_NE(c, cases.end()) << "no bad-input case for the command " << command[1];
    const Outcome o = testing::run_shell("timeout 120 " + std::string(CASKDEM_BINARY) + " " + c->second.arguments);
    EXPECT_EQ(o.status, 2) << c->second.arguments << "\n" << o.output;
    EXPECT_THAT(o.output, HasSubstr(c->second.message)) << c->second.arguments;
    EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << "one line: " << o.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << c->second.arguments << ": wrote before refusing";
  }
  EXPECT_EQ(commands, static_cast<int>(cases.size())) << "--help lists every command with a case here";

  // An earlier diagnosis to start from is read before anything is fitted or written.
  for (const std::string command : {"diagnose", "calibrate-measured"}) {
    const Outcome earlier = testing::run_shell("timeout 120 " + std::string(CASKDEM_BINARY) + " " + command + " " +
                                               good.string() + " --start-from " + bad_json.string() + " --out " + out);
    EXPECT_EQ(earlier.status, 2) << earlier.output;
    EXPECT_THAT(earlier.output, HasSubstr(bad_json.string() + ": not JSON")) << command;
    EXPECT_EQ(std::count(earlier.output.begin(), earlier.output.end(), '\n'), 1) << "one line: " << earlier.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << command << " --start-from: wrote before refusing";
  }

  // A command line that does not parse is one line too (CLI11 added a second).
  const Outcome o = run_caskdem("run");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << o.output;
}

}  // namespace
}  // namespace caskdem
