#include "flexmbd/io/loop_assembly.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/QR>

#include "flexmbd/io/initial_placement.hpp"
#include "flexmbd/io/loop_closure.hpp"
#include "flexmbd/joints/joint_kinematics.hpp"
#include "flexmbd/math/so3.hpp"

namespace flexmbd {
namespace io {
namespace {
// Gauss-Newton stops once the gaps are this small relative to the model's extent (metres; radians count as
// metres on a 1 m lever), far below CloseLoops' 1e-9; it converges in a handful of iterations from a start
// whose error is a fraction of a radian.
constexpr double kAssembledGap = 1.0e-14;
constexpr int kAssemblyIterations = 50;
constexpr int kHalvings = 20;
// The set positions are walked from the URDF's pose to their values in steps of at most this [rad or m], the
// loops closed at each: the assembly follows the branch the URDF draws (a slider-crank's rod does not fold back
// when its crank is set half a turn on), and each Gauss-Newton start lies well within its linearisation.
constexpr double kContinuationStep = 0.1;
// ... in at most this many increments (a crank set 16 turns on), so that a huge set value costs a bounded time.
constexpr int kMaxIncrements = 1000;
// Central differences of the gaps: the error, h^2 times the third derivative, stays near 1e-14 for links of
// metres, which slows the Newton convergence only by that factor.
constexpr double kGapDifferenceStep = 1.0e-7;
// Singular values below this fraction of the largest are taken as zero: directions the loops do not fix (a
// dead centre, a joint outside every loop) get no change.
constexpr double kRankThreshold = 1.0e-10;
// A loop drawn straight (every link along one line) is at a dead centre: the gaps along the line change only to
// second order, so no Gauss-Newton step narrows them. The free joint variables are then turned by this much
// [rad or m], enough for the first order to see the way out and small against any link, and the iteration goes
// on; a positive turn picks the branch on one side of the line.
constexpr double kDeadCentreNudge = 1.0e-3;

// One coordinate the assembly may change: variable `slot` of a joint, or (slot >= the joint's variables) a
// component of a spherical joint's relative rotation (or angular velocity) in Jp.
struct Coordinate {
  int joint;
  int slot;
};

// Whether the coordinate is a joint variable (not a component of a spherical joint's rotation).
bool IsJointVariable(const ModelSpec& spec, const Coordinate& c) {
  return c.slot < static_cast<int>(spec.joints[c.joint].initial_position.size());
}

std::vector<Coordinate> FreeCoordinates(const ModelSpec& spec, bool rates) {
  std::vector<Coordinate> free;
  for (size_t j = 0; j < spec.joints.size(); ++j) {
    const JointSpec& joint = spec.joints[j];
    if (joint.closes_loop) continue;
    const std::vector<bool>& set = rates ? joint.velocity_set : joint.position_set;
    for (size_t k = 0; k < set.size(); ++k) {
      if (!set[k]) free.push_back(Coordinate{static_cast<int>(j), static_cast<int>(k)});
    }
    if (joint.type == JointType::kSpherical) {
      for (int k = 0; k < 3; ++k) free.push_back(Coordinate{static_cast<int>(j), static_cast<int>(set.size()) + k});
    }
  }
  return free;
}

// Adds `change` to the free coordinates (positions, or rates when `rates`).
void Move(const std::vector<Coordinate>& free, const Eigen::VectorXd& change, bool rates, ModelSpec* spec) {
  for (size_t i = 0; i < free.size(); ++i) {
    JointSpec& joint = spec->joints[free[i].joint];
    const int n = static_cast<int>(joint.initial_position.size());
    if (free[i].slot < n) {
      (rates ? joint.initial_velocity : joint.initial_position)[free[i].slot] += change[i];
    } else if (rates) {
      joint.initial_angular_velocity[free[i].slot - n] += change[i];
    } else if (free[i].slot == n) {  // the three components of a rotation vector, together
      joint.initial_rotation = Exp(change.segment<3>(i)) * joint.initial_rotation;
    }
  }
}

class Assembler {
 public:
  Assembler(const std::vector<BodyMount>& free_bodies, bool rates, ModelSpec* spec)
      : free_bodies_(free_bodies), rates_(rates), spec_(spec), free_(FreeCoordinates(*spec, rates)) {}

  Eigen::VectorXd Gaps() const { return rates_ ? LoopMotionGaps(*spec_) : LoopPoseGaps(*spec_); }

  // The gaps as functions of the free coordinates, by central differences about the spec's values.
  Eigen::MatrixXd Jacobian() const {
    Eigen::MatrixXd J(Gaps().size(), free_.size());
    for (size_t i = 0; i < free_.size(); ++i) {
      const Eigen::VectorXd step = Eigen::VectorXd::Unit(free_.size(), i) * kGapDifferenceStep;
      J.col(i) = (GapsMoved(step) - GapsMoved(-step)) / (2.0 * kGapDifferenceStep);
    }
    return J;
  }

  // The least change that zeroes the gaps to first order: the minimum-norm least-squares step.
  Eigen::VectorXd LeastChange(const Eigen::VectorXd& gaps) const {
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver(Jacobian());
    solver.setThreshold(kRankThreshold);
    return solver.solve(-gaps);
  }

  Eigen::VectorXd GapsMoved(const Eigen::VectorXd& change) const {
    ModelSpec moved = *spec_;
    Move(free_, change, rates_, &moved);
    PlaceBodies(free_bodies_, &moved);
    return rates_ ? LoopMotionGaps(moved) : LoopPoseGaps(moved);
  }

  void Accept(const Eigen::VectorXd& change) {
    Move(free_, change, rates_, spec_);
    PlaceBodies(free_bodies_, spec_);
  }

  const std::vector<Coordinate>& free() const { return free_; }

 private:
  const std::vector<BodyMount>& free_bodies_;
  bool rates_;
  ModelSpec* spec_;
  std::vector<Coordinate> free_;
};

// The extent of the model: the tolerance's scale [m].
double Extent(const ModelSpec& spec) {
  double extent = 1.0;
  for (const BodySpec& body : spec.bodies) extent = std::max(extent, body.p_WB.norm());
  for (const BeamSpec& beam : spec.beams) extent = std::max(extent, beam.p_WB.norm() + beam.length);
  return extent;
}

// The nudge off a dead centre: kDeadCentreNudge on every free joint variable (not a spherical joint's rotation,
// which would tilt a planar loop out of its plane).
Eigen::VectorXd DeadCentreNudge(const ModelSpec& spec, const std::vector<Coordinate>& free) {
  Eigen::VectorXd nudge = Eigen::VectorXd::Zero(free.size());
  for (size_t i = 0; i < free.size(); ++i) {
    if (IsJointVariable(spec, free[i])) {
      nudge[i] = kDeadCentreNudge;
    }
  }
  return nudge;
}

// Gauss-Newton on the gaps (K2), its step halved while it widens them (far from the solution the linearisation
// may); stops at kAssembledGap or where no step narrows them (least squares: the loops cannot close), after one
// nudge off a dead centre.
void CloseByLeastChange(double extent, Assembler* positions, const ModelSpec& spec) {
  Eigen::VectorXd gaps = positions->Gaps();
  bool nudged = false;
  for (int iteration = 0; iteration < kAssemblyIterations; ++iteration) {
    if (gaps.lpNorm<Eigen::Infinity>() < kAssembledGap * extent) return;
    Eigen::VectorXd change = positions->LeastChange(gaps), next = positions->GapsMoved(change);
    for (int halving = 0; halving < kHalvings && next.norm() >= gaps.norm(); ++halving) {
      change /= 2.0;
      next = positions->GapsMoved(change);
    }
    if (next.norm() >= gaps.norm()) {
      if (nudged) return;
      nudged = true;
      change = DeadCentreNudge(spec, positions->free());
      next = positions->GapsMoved(change);
    }
    positions->Accept(change);
    gaps = next;
  }
}

// Each free angle of a joint (a rotation variable that moves nothing along the axis) turned by whole turns to
// the one nearest its value before the assembly: Gauss-Newton's steps may wind a loop's joints round, which
// moves no body but reads as turns of a spring or a stop's angle.
void UnwindTurns(const std::vector<Coordinate>& free, const std::vector<double>& before, ModelSpec* spec) {
  for (size_t i = 0; i < free.size(); ++i) {
    if (!IsJointVariable(*spec, free[i])) continue;
    JointSpec& joint = spec->joints[free[i].joint];
    const JointKinematics kinematics = MakeJointKinematics(joint);
    const bool rotates = std::any_of(kinematics.rotations.begin(), kinematics.rotations.end(),
                                     [&](const RotationFactor& factor) { return factor.variable == free[i].slot; });
    if (!rotates || !kinematics.translation_rates_Jp[free[i].slot].isZero()) continue;
    double& q = joint.initial_position[free[i].slot];
    q = before[i] + std::remainder(q - before[i], 2.0 * M_PI);
  }
}
}  // namespace

void AssembleLoops(const std::vector<BodyMount>& free_bodies, ModelSpec* spec) {
  const double extent = Extent(*spec);
  Assembler positions(free_bodies, false, spec);
  if (!positions.free().empty() && positions.Gaps().lpNorm<Eigen::Infinity>() >= kAssembledGap * extent) {
    std::vector<double> before;  // the free coordinates' values as drawn
    for (const Coordinate& c : positions.free()) {
      before.push_back(IsJointVariable(*spec, c) ? spec->joints[c.joint].initial_position[c.slot] : 0);
    }
    // the set positions, walked from the URDF's pose (zero) to their values
    std::vector<double*> set;
    std::vector<double> target;
    for (JointSpec& joint : spec->joints) {
      for (size_t k = 0; k < joint.position_set.size(); ++k) {
        if (!joint.position_set[k] || joint.closes_loop) continue;
        set.push_back(&joint.initial_position[k]);
        target.push_back(joint.initial_position[k]);
      }
    }
    double largest = 0;
    for (double value : target) largest = std::max(largest, std::abs(value));
    int increments = 1;
    if (largest > kContinuationStep) {
      const bool bounded = largest < kMaxIncrements * kContinuationStep;
      increments = bounded ? static_cast<int>(std::ceil(largest / kContinuationStep)) : kMaxIncrements;
    }
    for (int increment = 1; increment <= increments; ++increment) {
      for (size_t i = 0; i < set.size(); ++i) {
        *set[i] = increment == increments ? target[i] : target[i] * increment / increments;
      }
      PlaceBodies(free_bodies, spec);
      CloseByLeastChange(extent, &positions, *spec);
    }
    UnwindTurns(positions.free(), before, spec);
    PlaceBodies(free_bodies, spec);
  }
  // The gaps in the rates are linear in them: one step closes them; a second takes the round-off.
  Assembler rates(free_bodies, true, spec);
  for (int iteration = 0; iteration < 2 && !rates.free().empty(); ++iteration) {
    const Eigen::VectorXd motion_gaps = rates.Gaps();
    if (motion_gaps.lpNorm<Eigen::Infinity>() < kAssembledGap * extent) break;
    rates.Accept(rates.LeastChange(motion_gaps));
  }
}

}  // namespace io
}  // namespace flexmbd
