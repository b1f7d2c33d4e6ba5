// flexmbd_run stopped by SIGINT (Ctrl-C) or SIGTERM while it writes --bag and --csv: it ends the step in
// progress, closes both files and says where it stopped (docs/config.md, "output"). Killed outright, it once
// left the bag unindexed and the CSV's last row cut after 3 columns, with exit 130 and no word (explore23
// ros/runner_sigint).

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "../integration/helpers/csv_table.hpp"
#include "default_bag.hpp"
#include "flexmbd/common/exit_status.hpp"

namespace flexmbd {
namespace runner_interrupt_test {

// The pendulum released at 30 deg for far longer than the test waits: the run is certainly in progress when
// the signal comes, with a few hundred samples in the files.
constexpr char kLongRun[] = "joints: {B1: {initial: {position_deg: 30.0}}}\nsolver: {t_end: 10000.0}\n"
                            "output: {rate_hz: 100}\n";
// Long enough for the runner to load, build and write its first rows on a loaded machine.
constexpr std::chrono::milliseconds kRunBeforeSignal(1500);

std::string ReadText(const std::string& path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

struct Interrupted {
  int exit_status = -1;
  std::string errors, csv_path, bag_path;
};

// Starts the runner on kLongRun, sends it `signal` after kRunBeforeSignal and waits for it to end.
Interrupted RunAndSignal(int signal, const std::string& name) {
  Interrupted run;
  const std::string yaml = testing::TempDir() + name + ".yaml";
  std::ofstream(yaml) << kLongRun;
  run.csv_path = testing::TempDir() + name + ".csv";
  run.bag_path = testing::TempDir() + name + ".bag";
  const std::string errors = testing::TempDir() + name + ".err";
  const std::string urdf = std::string(FLEXMBD_SOURCE_DIR) + "/test/data/urdf/pendulum.urdf";
  const pid_t pid = fork();
  if (pid == 0) {
    if (!std::freopen("/dev/null", "w", stdout) || !std::freopen(errors.c_str(), "w", stderr)) _exit(127);
    execl(FLEXMBD_RUNNER, FLEXMBD_RUNNER, "--urdf", urdf.c_str(), "--config", yaml.c_str(), "--csv",
          run.csv_path.c_str(), "--bag", run.bag_path.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  std::this_thread::sleep_for(kRunBeforeSignal);
  kill(pid, signal);
  int status = 0;
  waitpid(pid, &status, 0);
  run.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.errors = ReadText(errors);
  return run;
}

// Every row of the CSV has the header's number of values and ends with its line break.
void ExpectWholeRows(const std::string& path) {
  const std::string text = ReadText(path);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  std::istringstream lines(text);
  std::string header, row;
  std::getline(lines, header);
  const long columns = std::count(header.begin(), header.end(), ',');
  for (long k = 1; std::getline(lines, row); ++k) {
    ASSERT_EQ(std::count(row.begin(), row.end(), ','), columns) << "row " << k << ": " << row;
  }
}

void ExpectClosedRecordings(const Interrupted& run) {
  EXPECT_EQ(run.exit_status, kExitInterrupted) << run.errors;
  EXPECT_NE(run.errors.find("flexmbd_run: interrupted at t = "), std::string::npos) << run.errors;
  ExpectWholeRows(run.csv_path);
  // Opening reads the bag's index: an unindexed bag throws here.
  const test::Samples bag = test::ReadDefaultBag(run.bag_path);
  const test::CsvTable csv = test::ReadCsv(run.csv_path);
  EXPECT_GT(csv.rows.size(), 1u);
  EXPECT_EQ(bag.joint_states.size(), csv.rows.size());
}

TEST(RunnerInterrupt, SigintClosesTheBagIndexedAndTheCsvWithWholeRows) {
  ExpectClosedRecordings(RunAndSignal(SIGINT, "runner_sigint"));
}

TEST(RunnerInterrupt, SigtermClosesTheBagIndexedAndTheCsvWithWholeRows) {
  ExpectClosedRecordings(RunAndSignal(SIGTERM, "runner_sigterm"));
}

}  // namespace runner_interrupt_test
}  // namespace flexmbd
