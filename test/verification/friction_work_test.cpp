// Coulomb friction never does positive work (docs/theory.md (F9)): the energy it dissipates, friction.<joint>.work,
// never falls from one row of the runner's CSV to the next, where the scheme holds a sliding direction or a mean force
// over a step or a projection's limiting steps in which the exact slip stops or turns. Run the user's way, through the
// runner at default settings: the slider-crank of test/data with friction on its slide, its crank driven into a dead
// centre and through two, and the two-link arm whose elbow slips, stops and breaks away from a residual slip.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "csv_books.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace friction_work_test {

const std::string kSliderCrank =
    "closures:\n  wrist_pin: {type: universal, parent: rod, child: slider, xyz: [0.3, 0.0, 0.0], axis: [0, 0, 1], "
    "axis2: [0, 1, 0]}\njoints:\n  crank_pin: {type: spherical}\n  slide: {friction: {mu_s: 0.3, mu_k: 0.2}}\n"
    "  crank_hinge: {drive: ";

struct Case {
  const char* urdf;
  std::string yaml;
  const char* work;  // the work's column
};

TEST(FrictionWork, NeverFallsWhereTheSlipStopsOrTurns) {
  std::string arm = test::SourceText("test/data/yaml/arm_ramp_starts_under_elbow_friction.yaml");
  const std::string ramp = "drive: {law: linear_ramp, value: -6.0, start: 0.5, duration: 1.0}";
  arm.replace(arm.find(ramp), ramp.size(), "drive: {law: sine, amplitude: -0.8, frequency: 1.0, start: 0.5}");
  const std::vector<Case> cases = {
      // Into the dead centre at pi, from rest (fell by 3.0e-8 J in the first step's projection, read -3.0e-8 J).
      {"test/data/urdf/slider_crank.urdf",
       kSliderCrank + "{law: cosine_ramp, offset: 1.0, value: 3.141592653589793, duration: 0.5}}\n"
                      "solver: {t_end: 1.0, gravity: [0.0, -9.81, 0.0]}\noutput: {rate_hz: 0}\n",
       "friction.slide.work"},
      // Through the dead centres at pi and 2 pi (fell by 6.1e-9 J where the slide broke away at 0.845 s).
      {"test/data/urdf/slider_crank.urdf",
       kSliderCrank + "{law: linear_ramp, offset: 1.0, value: 7.283185307179586, duration: 1.0}}\n"
                      "solver: {t_end: 1.2, gravity: [0.0, -9.81, 0.0]}\noutput: {rate_hz: 0}\n",
       "friction.slide.work"},
      // The elbow stuck at a residual slip of -0.106 rad/s breaks away the other way (fell by 1.3e-5 J at 0.86 s).
      {"test/data/urdf/two_link_arm.urdf", arm, "friction.B2.work"}};
  for (const Case& c : cases) {
    const std::string csv = testing::TempDir() + "friction_work.csv";
    std::string yaml = c.yaml;
    yaml.replace(yaml.find("output: {rate_hz: 0}"), 20, "output: {rate_hz: 0, csv: " + csv + "}");
    const std::string output = test::RunnerOutput(c.urdf, yaml, "friction_work");
    SCOPED_TRACE(output);
    const test::CsvTable table = test::ReadCsv(csv);
    ASSERT_FALSE(table.rows.empty());
    EXPECT_EQ(test::LargestFall(table, c.work), 0.0);
    EXPECT_GT(table.rows.back().at(table.Column(c.work)), 0.0);
    // The part friction does not book is the scheme's, and the books still close to Newton's tolerance: 1e-6 of the
    // steps' terms over their travel (measured 7e-11 and 1.1e-8 on the slider-crank, 8e-8 on the arm, as before).
    const test::CsvBooks books = test::BooksAt(table, table.rows.back());
    EXPECT_LT(std::abs(books.imbalance), 1e-6 * books.throughput);
  }
}

}  // namespace friction_work_test
}  // namespace flexmbd
