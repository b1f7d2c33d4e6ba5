// The command-line runner on bad input: one clear line on stderr naming the file and field, and a non-zero
// exit status (2 for bad input), never a crash. Runs the real flexmbd_run binary.

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "flexmbd/io/text_file.hpp"
#include "../integration/helpers/file_size_limit.hpp"
#include "cut_csv.hpp"

namespace runner_exit_test {

struct RunOutcome {
  int exit_status = -1;
  std::string stderr_text;
};

RunOutcome RunRunner(const std::string& arguments) {
  const std::string err_path = testing::TempDir() + "runner_stderr.txt";
  const std::string command = std::string(FLEXMBD_RUNNER) + " " + arguments + " > /dev/null 2> " + err_path;
  const int status = std::system(command.c_str());
  RunOutcome out;
  out.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_path);
  std::ostringstream text;
  text << err.rdbuf();
  out.stderr_text = text.str();
  return out;
}

std::string Data(const std::string& relative) { return std::string(FLEXMBD_SOURCE_DIR) + "/test/data/" + relative; }

// Writes a file (YAML or URDF) for one test and returns its path.
std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

constexpr int kBadInputExit = 2;

TEST(RunnerExit, MalformedUrdfExitsWithTwoAndNamesFile) {
  const RunOutcome out = RunRunner("--urdf " + Data("urdf/malformed_invalid.urdf") + " --config " +
                                   Data("yaml/pendulum.yaml"));
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_NE(out.stderr_text.find("malformed_invalid.urdf"), std::string::npos) << out.stderr_text;
}

TEST(RunnerExit, MovingLinkWithoutInertiaExitsWithTwo) {
  const RunOutcome out = RunRunner("--urdf " + Data("urdf/no_inertia_invalid.urdf") + " --config \"\"");
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_NE(out.stderr_text.find("inertial"), std::string::npos) << out.stderr_text;
}

TEST(RunnerExit, NegativeMassExitsWithTwo) {
  const RunOutcome out = RunRunner("--urdf " + Data("urdf/negative_mass_invalid.urdf") + " --config \"\"");
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_NE(out.stderr_text.find("mass"), std::string::npos) << out.stderr_text;
}

TEST(RunnerExit, UnknownJointNameExitsWithTwoAndListsJoints) {
  const std::string yaml = WriteFile("unknown_joint.yaml", "joints:\n  B7:\n    damper: {c: 1.0}\n");
  const RunOutcome out = RunRunner("--urdf " + Data("urdf/pendulum.urdf") + " --config " + yaml);
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_NE(out.stderr_text.find("joints.B7"), std::string::npos) << out.stderr_text;
}

TEST(RunnerExit, NegativeStiffnessExitsWithTwoAndNamesField) {
  const std::string yaml = WriteFile("negative_k.yaml", "joints:\n  B1:\n    spring: {k: -3.0}\n");
  const RunOutcome out = RunRunner("--urdf " + Data("urdf/pendulum.urdf") + " --config " + yaml);
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_NE(out.stderr_text.find("joints.B1.spring.k"), std::string::npos) << out.stderr_text;
}

TEST(RunnerExit, UnknownKeyExitsWithTwoAndSuggests) {
  const std::string yaml = WriteFile("unknown_key.yaml", "solver: {dtt: 0.01}\n");
  const RunOutcome out = RunRunner("--urdf " + Data("urdf/pendulum.urdf") + " --config " + yaml);
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_NE(out.stderr_text.find("did you mean 'dt'"), std::string::npos) << out.stderr_text;
}

TEST(RunnerExit, RhoInfBelowSchemeRangeExitsWithTwo) {
  const std::string yaml = WriteFile("low_rho.yaml", "solver: {rho_inf: 0.2}\n");
  const RunOutcome out = RunRunner("--urdf " + Data("urdf/pendulum.urdf") + " --config " + yaml);
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_NE(out.stderr_text.find("solver.rho_inf: 0.2"), std::string::npos) << out.stderr_text;
}

TEST(RunnerExit, DirectoryAsConfigExitsWithTwo) {
  const RunOutcome out = RunRunner("--urdf " + Data("urdf/pendulum.urdf") + " --config " + Data("yaml"));
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_NE(out.stderr_text.find("it is a directory; expected a text file"), std::string::npos) << out.stderr_text;
}

TEST(RunnerExit, JointCycleExitsWithTwoAndNamesTheJoints) {
  const std::string inertial =
      "<inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>";
  const std::string urdf = WriteFile(
      "cycle.urdf", "<robot name=\"r\"><link name=\"world\"/><link name=\"a\">" + inertial +
                        "</link><link name=\"b\">" + inertial + "</link><link name=\"c\">" + inertial +
                        "</link><joint name=\"j1\" type=\"continuous\"><parent link=\"world\"/><child link=\"a\"/>"
                        "</joint><joint name=\"j2\" type=\"continuous\"><parent link=\"b\"/><child link=\"c\"/>"
                        "</joint><joint name=\"j3\" type=\"continuous\"><parent link=\"c\"/><child link=\"b\"/>"
                        "</joint></robot>");
  const RunOutcome out = RunRunner("--urdf " + urdf + " --config \"\"");
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_NE(out.stderr_text.find("cycle.urdf: joints 'j2', 'j3' form a cycle"), std::string::npos) << out.stderr_text;
}

TEST(RunnerExit, NothingToMoveExitsWithTwo) {
  const std::string urdf = WriteFile("world_only.urdf", "<robot name=\"r\"><link name=\"world\"/></robot>");
  const RunOutcome out = RunRunner("--urdf " + urdf + " --config \"\"");
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_NE(out.stderr_text.find("world_only.urdf: nothing can move"), std::string::npos) << out.stderr_text;
}

TEST(RunnerExit, UnboundedOutputExitsWithTwoBeforeWriting) {
  const std::string csv = testing::TempDir() + "unbounded.csv";
  std::remove(csv.c_str());
  const std::string yaml = WriteFile("unbounded.yaml", "solver: {t_end: 1.0e300}\noutput: {rate_hz: 1.0e6}\n");
  const RunOutcome out = RunRunner("--urdf " + Data("urdf/pendulum.urdf") + " --config " + yaml + " --csv " + csv);
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_NE(out.stderr_text.find("output.rate_hz 1e+06 Hz and solver.t_end 1e+300 s"), std::string::npos)
      << out.stderr_text;
  EXPECT_FALSE(std::ifstream(csv).good()) << "the CSV was created";
}

TEST(RunnerExit, MissingArgumentsPrintUsageAndExitWithOne) {
  const RunOutcome out = RunRunner("--config");
  EXPECT_EQ(out.exit_status, 1);
  EXPECT_NE(out.stderr_text.find("usage"), std::string::npos) << out.stderr_text;
}

constexpr int kRunFailedExit = 3;

// The double pendulum of config/double_pendulum/: 10 s at 100 samples/s, 1001 rows of about 600 bytes.
std::string DoublePendulumCase() {
  const std::string root = FLEXMBD_SOURCE_DIR;
  return "--urdf " + root + "/config/double_pendulum/double_pendulum.urdf --config " + root +
         "/config/double_pendulum/double_pendulum.yaml";
}

// The freeplay oscillator of test/data (a disk of 0.5 kg m^2 between linear elastic stops of 20 N m/rad at
// +-2 deg, started at 0.41 rad/s) on fixed steps of 0.1 s with dt_min 0.05 s: a contact lasts pi sqrt(I / k) =
// 0.497 s, and resolving it in 20 steps (docs/theory.md (C6)) needs steps of about 0.025 s, below dt_min. The run
// fails in its first contact, and the message names what to change for fixed steps; doing so (here the smaller
// dt_min) runs the case.
std::string FreeplayOnFixedSteps(const std::string& name, const std::string& dt_min) {
  return "--urdf " + Data("urdf/freeplay_disk.urdf") + " --config " +
         WriteFile(name, "joints:\n  hinge:\n    initial: {velocity: 0.41166339}\n"
                         "    backlash: {lower_deg: -2.0, upper_deg: 2.0,"
                         " stop: {type: elastic, law: linear, stiffness: 20.0}}\n"
                         "solver: {t_end: 2.0, gravity: [0.0, 0.0, 0.0], adaptive: false, dt: 0.1, dt_min: " +
                             dt_min + "}\n");
}

TEST(RunnerExit, FixedStepsTooLongForAContactExitWithThreeAndSayWhatToTry) {
  const RunOutcome failed = RunRunner(FreeplayOnFixedSteps("freeplay_long_steps.yaml", "0.05"));
  EXPECT_EQ(failed.exit_status, kRunFailedExit);
  EXPECT_NE(failed.stderr_text.find("run failed: step size fell below dt_min"), std::string::npos)
      << failed.stderr_text;
  EXPECT_NE(failed.stderr_text.find("try a smaller solver.dt (fixed steps may leave the motion unresolved), "
                                    "adaptive steps, or a smaller solver.dt_min"),
            std::string::npos)
      << failed.stderr_text;
  EXPECT_EQ(RunRunner(FreeplayOnFixedSteps("freeplay_long_steps_hint_taken.yaml", "0.001")).exit_status, 0);
}

// A static analysis has load increments and Newton iterations, not time steps: its failure says what it did and
// nothing of steps, dt or dt_min (which read as the dynamic run's).
void ExpectStaticWords(const std::string& message) {
  for (const char* dynamic_word : {"with step", "dt_min", "solver.dt", "step size"}) {
    EXPECT_EQ(message.find(dynamic_word), std::string::npos) << dynamic_word << " in: " << message;
  }
}

TEST(RunnerExit, StaticAnalysisThatDoesNotConvergeSaysItsIncrementAndIterations) {
  // The simple pendulum held at 90 deg has its equilibrium 90 deg away: one Newton iteration cannot reach it.
  const RunOutcome failed = RunRunner(
      "--urdf " + Data("urdf/simple_pendulum.urdf") + " --config " +
      WriteFile("static_one_iteration.yaml", "joints: {hinge: {initial: {position_deg: 90.0}}}\n"
                                             "solver: {analysis: static, load_steps: 2, max_iterations: 1}\n"));
  EXPECT_EQ(failed.exit_status, kRunFailedExit);
  EXPECT_NE(failed.stderr_text.find("run failed: static analysis failed in load increment 1 of 2 (load factor "
                                    "0.5): Newton did not converge in 1 iterations (solver.max_iterations 1); "
                                    "worst residual at "),
            std::string::npos)
      << failed.stderr_text;
  EXPECT_NE(failed.stderr_text.find("; try more load increments (solver.load_steps), a larger "
                                    "solver.max_iterations or solver.tol"),
            std::string::npos)
      << failed.stderr_text;
  ExpectStaticWords(failed.stderr_text);
}

TEST(RunnerExit, StaticAnalysisOfAnUnheldJointSaysItsMatrixIsSingular) {
  // A block on a frictionless incline with nothing to hold it (test/data/urdf/incline.urdf): no equilibrium.
  const RunOutcome failed =
      RunRunner("--urdf " + Data("urdf/incline.urdf") + " --config " +
                WriteFile("static_unheld.yaml", "solver: {analysis: static}\n"));
  EXPECT_EQ(failed.exit_status, kRunFailedExit);
  EXPECT_NE(failed.stderr_text.find("run failed: static analysis failed in load increment 1 of 10 (load factor "
                                    "0.1): singular iteration matrix after "),
            std::string::npos)
      << failed.stderr_text;
  EXPECT_NE(failed.stderr_text.find("check that every part is held in the equilibrium"), std::string::npos)
      << failed.stderr_text;
  ExpectStaticWords(failed.stderr_text);
}

TEST(RunnerExit, StaticAnalysisOfAJointOnlyFrictionHoldsSaysFrictionIsLeftOut) {
  // Found as a user: a block held on its incline by friction (mu_s 0.7 > tan 30 deg) has no static equilibrium, as
  // friction is left out of it; the message said to hold every part, not that the friction given was left out.
  const RunOutcome failed =
      RunRunner("--urdf " + Data("urdf/incline.urdf") + " --config " +
                WriteFile("static_friction.yaml", "joints: {slide: {friction: {mu_s: 0.7, mu_k: 0.6}}}\n"
                                                  "solver: {analysis: static}\n"));
  EXPECT_EQ(failed.exit_status, kRunFailedExit);
  EXPECT_NE(failed.stderr_text.find("; friction (on slide) is left out of a static analysis: to hold a joint where "
                                    "friction would, give it initial.static_hold\n"),
            std::string::npos)
      << failed.stderr_text;
}

TEST(RunnerExit, CsvOnAFullDeviceExitsWithThreeInOneLineNamingTheFile) {
  const RunOutcome out = RunRunner(DoublePendulumCase() + " --csv /dev/full");
  EXPECT_EQ(out.exit_status, kRunFailedExit);
  EXPECT_EQ(out.stderr_text,
            "flexmbd_run: output.csv: writing '/dev/full' failed (No space left on device); the file holds nothing\n");
}

// Runs the double pendulum (`config`: its YAML's path) with a 100 kB cap on the runner's files (RLIMIT_FSIZE,
// inherited), which stops the CSV at about a sixth of the run: exit status 3, one line naming the file and the
// rows it holds, and whole rows as many as it says.
void ExpectCappedCsvKeepsWholeRows(const std::string& config, const std::string& csv_name) {
  const std::string csv = testing::TempDir() + csv_name;
  RunOutcome out;
  {
    const flexmbd::test::FileSizeLimit cap(100000);
    out = RunRunner("--urdf " + std::string(FLEXMBD_SOURCE_DIR) +
                    "/config/double_pendulum/double_pendulum.urdf --config " + config + " --csv " + csv);
  }
  EXPECT_EQ(out.exit_status, kRunFailedExit);
  EXPECT_EQ(std::count(out.stderr_text.begin(), out.stderr_text.end(), '\n'), 1) << out.stderr_text;
  EXPECT_EQ(out.stderr_text.find("flexmbd_run: output.csv: writing '" + csv + "' failed (File too large); the file "
                                 "holds its header row and the first "),
            0u)
      << out.stderr_text;
  flexmbd::test::ExpectWholeRowsAsClaimed(csv, out.stderr_text);
}

TEST(RunnerExit, CsvOnADiskFillingUpMidRunExitsWithThreeKeepingWholeRows) {
  ExpectCappedCsvKeepsWholeRows(std::string(FLEXMBD_SOURCE_DIR) + "/config/double_pendulum/double_pendulum.yaml",
                                "capped_run.csv");
}

TEST(RunnerExit, CsvFailingOnTheWriterThreadOfTwoSolverThreadsExitsWithThreeKeepingWholeRows) {
  // With solver.threads 2 the runner writes the samples on a thread of its own: the failure comes from there, is
  // reported once, and the file keeps whole rows, as on one thread (the test above).
  std::string yaml =
      flexmbd::ReadTextFile(std::string(FLEXMBD_SOURCE_DIR) + "/config/double_pendulum/double_pendulum.yaml", "YAML");
  yaml.replace(yaml.find("\nsolver:\n"), 9, "\nsolver:\n  threads: 2\n");
  ExpectCappedCsvKeepsWholeRows(WriteFile("double_pendulum_two_threads.yaml", yaml), "capped_run_two_threads.csv");
}

TEST(RunnerExit, CheckLoadsTheCaseAndExitsZeroWithoutRunning) {
  const std::string csv = testing::TempDir() + "check_only.csv";
  std::remove(csv.c_str());
  const RunOutcome out =
      RunRunner("--urdf " + Data("urdf/pendulum.urdf") + " --config " + Data("yaml/pendulum.yaml") + " --csv " + csv +
                " --check");
  EXPECT_EQ(out.exit_status, 0) << out.stderr_text;
  EXPECT_FALSE(std::ifstream(csv).good()) << "--check ran the case and wrote " << csv;
}

TEST(RunnerExit, CheckWithColumnsWritesTheCsvHeaderAndNoSample) {
  // scripts/sweep.py checks its metrics' columns against this header before any case runs.
  const std::string columns = testing::TempDir() + "check_columns.csv";
  const RunOutcome out = RunRunner("--urdf " + Data("urdf/pendulum.urdf") + " --config " + Data("yaml/pendulum.yaml") +
                                   " --check --columns " + columns);
  EXPECT_EQ(out.exit_status, 0) << out.stderr_text;
  std::ifstream file(columns);
  std::string header, row;
  std::getline(file, header);
  EXPECT_EQ(header.rfind("t,joint.B1.position,joint.B1.velocity,joint.B1.effort,", 0), 0u) << header;
  EXPECT_FALSE(std::getline(file, row)) << row;
}

TEST(RunnerExit, CheckOfBadInputExitsWithTwoAndNamesField) {
  const std::string yaml = WriteFile("check_negative_k.yaml", "joints:\n  B1:\n    spring: {k: -3.0}\n");
  const RunOutcome out = RunRunner("--check --urdf " + Data("urdf/pendulum.urdf") + " --config " + yaml);
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_NE(out.stderr_text.find("joints.B1.spring.k"), std::string::npos) << out.stderr_text;
}

// output.csv naming a directory (explore6 D6): --check passed it and only the run refused it, in a line without the
// YAML file. Now both refuse it before anything runs, in one line naming the file, the field and the expected form.
TEST(RunnerExit, DirectoryAsOutputCsvIsBadInputForCheckAndRunNamingTheFile) {
  const std::string directory = testing::TempDir() + "csv_dir";
  std::system(("mkdir -p " + directory).c_str());
  const std::string yaml = WriteFile("csv_is_a_directory.yaml", "output: {csv: " + directory + "}\n");
  const std::string expected = "flexmbd_run: " + yaml + ": output.csv: '" + directory +
                               "' is a directory; expected a writable file path (\"\" for none)\n";
  for (const std::string check : {" --check", ""}) {
    const RunOutcome out = RunRunner("--urdf " + Data("urdf/pendulum.urdf") + " --config " + yaml + check);
    EXPECT_EQ(out.exit_status, kBadInputExit) << check;
    EXPECT_EQ(out.stderr_text, expected) << check;
  }
}

TEST(RunnerExit, OutputCsvInAMissingDirectoryIsBadInputForCheck) {
  const std::string csv = testing::TempDir() + "no_such_dir/run.csv";
  const std::string yaml = WriteFile("csv_in_missing_dir.yaml", "output: {csv: " + csv + "}\n");
  const RunOutcome out = RunRunner("--check --urdf " + Data("urdf/pendulum.urdf") + " --config " + yaml);
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_EQ(out.stderr_text, "flexmbd_run: " + yaml + ": output.csv: '" + csv + "' is in '" + testing::TempDir() +
                                 "no_such_dir', which is not an existing directory; expected a writable file path "
                                 "(\"\" for none)\n");
}

TEST(RunnerExit, DirectoryGivenToCsvOrBagFlagIsBadInputForCheckNamingTheFlag) {
  for (const std::string flag : {"--csv", "--bag"}) {
    const RunOutcome out = RunRunner("--check --urdf " + Data("urdf/pendulum.urdf") + " --config " +
                                     Data("yaml/pendulum.yaml") + " " + flag + " /tmp");
    EXPECT_EQ(out.exit_status, kBadInputExit) << flag;
    EXPECT_EQ(out.stderr_text, "flexmbd_run: " + flag + ": '/tmp' is a directory; expected a writable file path "
                                                        "(\"\" for none)\n");
  }
}

TEST(RunnerExit, QuotedNumberOrYesForABooleanIsBadInputForCheck) {
  const std::string quoted = WriteFile("quoted_k.yaml", "joints:\n  B1:\n    spring: {k: \"100\"}\n");
  const std::string yes = WriteFile("adaptive_yes.yaml", "solver:\n  adaptive: yes\n");
  for (const std::string& yaml : {quoted, yes}) {
    const RunOutcome out = RunRunner("--check --urdf " + Data("urdf/pendulum.urdf") + " --config " + yaml);
    EXPECT_EQ(out.exit_status, kBadInputExit) << yaml;
    EXPECT_NE(out.stderr_text.find(yaml + ": "), std::string::npos) << out.stderr_text;
  }
}

// solver.eigen settings a user met without a word or with the wrong exit (explore23 bad/eigen, bad/aero): the run of
// `yaml` on `urdf` (test/data) is bad input, and its line says `message`.
void ExpectBadInputSaying(const std::string& urdf, const std::string& yaml, const std::string& message) {
  const RunOutcome out = RunRunner("--urdf " + Data(urdf) + " --config " + yaml);
  EXPECT_EQ(out.exit_status, kBadInputExit) << out.stderr_text;
  EXPECT_NE(out.stderr_text.find(message), std::string::npos) << out.stderr_text;
}

TEST(RunnerExit, SparseEigenOfAnAeroSectionIsBadInputNamingTheField) {
  // Once exit 3 "eigen-analysis failed" after the sweep had started.
  const std::string yaml = WriteFile(
      "sparse_aero.yaml",
      "joints: {flap: {drive: {law: constant, value: 0.0}}, plunge: {spring: {k: 7696.9}}, "
      "pitch: {spring: {k: 2886.3}}}\n"
      "aero: {sections: {hp: {plunge: plunge, pitch: pitch, flap: flap, semichord: 0.5, a: -0.2, c: 0.6, "
      "velocity: 10.0}}}\n"
      "solver: {analysis: eigen, gravity: [0, 0, 0], eigen: {method: sparse, sweep: {airspeed: [10, 20]}}}\n");
  ExpectBadInputSaying("urdf/hodges_pierce_section.urdf", yaml,
                       "solver.eigen.method: sparse cannot take the model's element states (aero section hp mu_1, "
                       "aero inflow); expected method: dense or auto");
}

TEST(RunnerExit, ShiftWithDenseEigenIsBadInputNamingTheField) {
  const std::string yaml =
      WriteFile("shift_dense.yaml", "solver: {analysis: eigen, eigen: {method: dense, shift_hz: 3.0}}\n");
  ExpectBadInputSaying("urdf/pendulum.urdf", yaml,
                       "solver.eigen.shift_hz: 3.0 picks the modes nearest it for the sparse method, and method: "
                       "dense finds every mode");
}

TEST(RunnerExit, MoreModesThanTheModelHasAreAllPrintedWithAWarning) {
  // The pendulum has one degree of freedom.
  const std::string yaml = WriteFile("modes_50.yaml", "solver: {analysis: eigen, eigen: {modes: 50}}\n");
  const RunOutcome out = RunRunner("--urdf " + Data("urdf/pendulum.urdf") + " --config " + yaml);
  EXPECT_EQ(out.exit_status, 0) << out.stderr_text;
  EXPECT_EQ(out.stderr_text,
            "flexmbd_run: warning: solver.eigen.modes: 50 asked for, the model has 1; all 1 printed\n");
}

// A pendulum on a revolute hinge whose URDF <limit> is +-1.5 rad: a user typed degrees under its radian keys (explore
// D5), and the run went ahead.
std::string LimitedHingeCase(const std::string& name, const std::string& joint_yaml) {
  const std::string urdf = WriteFile(
      "limited_hinge.urdf",
      "<robot name=\"r\"><link name=\"world\"/><link name=\"arm\"><inertial><origin xyz=\"0 0 -1\"/>"
      "<mass value=\"1\"/><inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" iyy=\"0.01\" iyz=\"0\" izz=\"0.01\"/>"
      "</inertial></link><joint name=\"hinge\" type=\"revolute\"><parent link=\"world\"/><child link=\"arm\"/>"
      "<axis xyz=\"0 1 0\"/><limit lower=\"-1.5\" upper=\"1.5\" effort=\"1\" velocity=\"1\"/></joint></robot>");
  return "--urdf " + urdf + " --config " +
         WriteFile(name, "joints: {hinge: " + joint_yaml + "}\nsolver: {t_end: 0.01}\n");
}

// The limited hinge with `joint_yaml` runs (exit 0) and stderr holds the one line "flexmbd_run: warning: <yaml>: " +
// `warning` (empty `warning`: nothing on stderr).
void ExpectRunWithWarning(const std::string& yaml_name, const std::string& joint_yaml, const std::string& warning) {
  const RunOutcome out = RunRunner(LimitedHingeCase(yaml_name, joint_yaml));
  EXPECT_EQ(out.exit_status, 0) << out.stderr_text;
  EXPECT_EQ(out.stderr_text,
            warning.empty() ? "" : "flexmbd_run: warning: " + testing::TempDir() + yaml_name + ": " + warning + "\n");
}

TEST(RunnerExit, InitialPositionOutsideTheUrdfLimitIsAWarningNamingTheDegreeKey) {
  ExpectRunWithWarning("initial_30.yaml", "{initial: {position: 30}}",
                       "joints.hinge.initial.position: 30 [rad] is outside the URDF <limit> [-1.5, 1.5] [rad] of "
                       "joint 'hinge': without stops (backlash) nothing holds the joint to its <limit>; if 30 is in "
                       "degrees, write position_deg: 30");
}

TEST(RunnerExit, StopOutsideTheUrdfLimitIsAWarningAndTheRunGoesOn) {
  ExpectRunWithWarning("stop_30.yaml", "{backlash: {lower: -1.0, upper: 30}}",
                       "joints.hinge.backlash.upper: 30 [rad] is outside the URDF <limit> [-1.5, 1.5] [rad] of joint "
                       "'hinge': this stop, not the <limit>, bounds the motion; if 30 is in degrees, write "
                       "upper_deg: 30");
  ExpectRunWithWarning("stop_30_deg.yaml", "{backlash: {lower: -1.0, upper_deg: 30}}", "");
}

TEST(RunnerExit, SineDriveWithoutAFrequencyExitsWithTwoAndNamesTheKey) {
  // The frequency defaulted to 0 Hz: the drive held the hinge at amplitude sin(phase) = 0 for the whole run.
  const RunOutcome out =
      RunRunner(LimitedHingeCase("sine_no_frequency.yaml", "{drive: {law: sine, amplitude_deg: 20}}"));
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_EQ(out.stderr_text, "flexmbd_run: " + testing::TempDir() +
                                 "sine_no_frequency.yaml: joints.hinge.drive: missing key 'frequency'; expected a "
                                 "frequency > 0 [Hz] (a sine without it is a constant: law: constant)\n");
}

TEST(RunnerExit, JointPastTheEndOfABeamExitsWithTwoAndSaysSo) {
  // test/data/urdf/beam_arm.urdf hinges its tip 1 m out along the beam 'arm'; here the beam is 0.5 m long.
  const std::string yaml = WriteFile(
      "short_arm.yaml",
      "beams: {arm: {length: 0.5, elements: 2, order: 3, section: {EA: 1.0e7, GA2: 4.0e6, GA3: 4.0e6, GJ: 50.0, "
      "EI2: 80.0, EI3: 100.0, m: 2.5}}}\nsolver: {t_end: 0.01}\n");
  const RunOutcome out = RunRunner("--urdf " + Data("urdf/beam_arm.urdf") + " --config " + yaml);
  EXPECT_EQ(out.exit_status, kBadInputExit);
  EXPECT_EQ(out.stderr_text, "flexmbd_run: " + Data("urdf/beam_arm.urdf") + " + " + yaml +
                                 ": joint 'tip_hinge': x = 1 m on beam 'arm' is past its end (length 0.5 m, 2 "
                                 "element(s) of order 3: nodes 0..6 every 0.08333333333333333 m, the nearest node 6 "
                                 "at 0.5 m); expected a node position [m]: 0, 0.08333333333333333, "
                                 "0.16666666666666666, 0.25, 0.3333333333333333, 0.4166666666666667, 0.5\n");
}

}  // namespace runner_exit_test
