// The loader's assembly of a loop drawn open, run the user's way (flexmbd_run on YAML): a four-bar drawn with every
// link along +x (four_bar_straight.urdf) is at a dead centre, where the gaps along the line change only to second
// order. Crank 0 was refused ("the loop does not close ... 0.2 m") though it closes, and every other crank angle
// left the rocker whole turns from the drawing (10.30 rad for -2.268), which a rocker spring read as 11.61 J
// instead of 1.52 J (docs/theory.md, "Assembly of the initial configuration").

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../integration/helpers/csv_table.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace loop_assembly_test {

// The assembled loop closes to 1e-14 of the model's extent (K2) and the loader fits the closure to round-off, so
// the rocker's angle is the circle intersection's to the round-off of the angles, 1e-12 rad; 1e-9 leaves room for
// the central differences of the Gauss-Newton Jacobian, which only slow the convergence.
constexpr double kClosed = 1.0e-9;
constexpr double kCrank = 0.1, kCoupler = 0.35, kRocker = 0.25, kGround = 0.4;
constexpr double kRockerSpring = 0.2;  // N m/rad, rest 0: the drawing

// The rocker's angle from the drawing (+x) with the crank at `crank`, on the branch `side` (+1: C to the left of
// B -> D): the intersection of the circles about B (coupler) and D (rocker).
double RockerAngle(double crank, int side) {
  const double bx = kCrank * std::cos(crank), by = kCrank * std::sin(crank);
  const double dx = kGround - bx, dy = -by, L = std::hypot(dx, dy);
  const double along = (kCoupler * kCoupler - kRocker * kRocker + L * L) / (2.0 * L);
  const double across = std::sqrt(kCoupler * kCoupler - along * along);
  const double cx = bx + along * dx / L - side * across * dy / L, cy = by + along * dy / L + side * across * dx / L;
  return std::atan2(cy, cx - kGround);
}

// The first row (t = 0) of a short run with the crank set at `crank` and a spring on the rocker, without gravity.
std::vector<double> StartRow(double crank, test::CsvTable* csv, const std::string& name) {
  const std::string path = testing::TempDir() + name + ".csv";
  test::RunnerOutput("test/data/urdf/four_bar_straight.urdf",
                     "closures:\n"
                     "  rocker_pin: {type: universal, parent: coupler, child: rocker, xyz: [0.35, 0.0, 0.0],\n"
                     "               child_xyz: [0.25, 0.0, 0.0], axis: [0, 0, 1], axis2: [0, 1, 0]}\n"
                     "joints:\n"
                     "  crank_pin: {type: spherical}\n"
                     "  crank_hinge: {initial: {position: " +
                         std::to_string(crank) +
                         "}}\n"
                         "  rocker_hinge: {spring: {k: 0.2}}\n"
                         "solver: {t_end: 1.0e-3, dt: 1.0e-3, gravity: [0, 0, 0]}\n"
                         "output: {rate_hz: 0, csv: " +
                         path + "}\n",
                     name);
  *csv = test::ReadCsv(path);
  return csv->rows.empty() ? std::vector<double>() : csv->rows.front();
}

TEST(LoopAssembly, AFourBarDrawnStraightClosesFromItsDeadCentreToTheNearestTurn) {
  // Crank 0: C at [0.35, +-0.2449], the rocker at +-1.7721542 rad; the other angles on whichever branch the walk
  // from the drawing reaches, but within half a turn of the drawing, and the spring's energy k q^2 / 2 of that.
  for (const double crank : {0.0, -1.0, 0.3, 1.2, 2.0, 3.0}) {
    test::CsvTable csv;
    const std::string name = "four_bar_straight_" + std::to_string(static_cast<int>(std::lround(crank * 10)));
    const std::vector<double> row = StartRow(crank, &csv, name);
    ASSERT_FALSE(row.empty()) << crank;
    EXPECT_NEAR(row[csv.Column("joint.crank_hinge.position")], crank, 1.0e-12);
    const double rocker = row[csv.Column("joint.rocker_hinge.position")];
    const double upper = RockerAngle(crank, 1), lower = RockerAngle(crank, -1);
    const double expected = std::abs(rocker - upper) < std::abs(rocker - lower) ? upper : lower;
    EXPECT_NEAR(rocker, expected, kClosed) << "crank " << crank << ": branches " << upper << ", " << lower;
    EXPECT_NEAR(row[csv.Column("energy.potential")], 0.5 * kRockerSpring * expected * expected, kClosed)
        << "crank " << crank;
  }
}

}  // namespace loop_assembly_test
}  // namespace flexmbd
