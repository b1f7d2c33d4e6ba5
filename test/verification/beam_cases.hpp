#pragma once
// Hand-written beam models shared by the beam verification tests.

#include <cstdio>
#include <string>

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace test {

// An isotropic section: axial EA, shear GA (both directions), torsion GJ, bending EI (both directions),
// mass per length m and mass moments per length (torsional rho J, bending rho I about y and z).
inline BeamSectionSpec Section(double EA, double GA, double GJ, double EI, double m, double rhoJ, double rhoI) {
  BeamSectionSpec s;
  s.stiffness.diagonal() << EA, GA, GA, GJ, EI, EI;
  s.mass_per_length = m;
  s.inertia_per_length = Vec3(rhoJ, rhoI, rhoI);
  return s;
}

// A cantilever along +x clamped at the origin (fixed joint to the world), no gravity.
inline ModelSpec Cantilever(double length, int elements, int order, const BeamSectionSpec& section) {
  ModelSpec spec;
  spec.source = "cantilever (test)";
  BeamSpec beam;
  beam.name = "beam";
  beam.length = length;
  beam.elements = elements;
  beam.order = order;
  beam.section = section;
  spec.beams.push_back(beam);
  JointSpec clamp;
  clamp.name = "clamp";
  clamp.type = JointType::kFixed;
  clamp.child = "beam";
  spec.joints.push_back(clamp);
  spec.solver.gravity = Vec3::Zero();
  spec.output.rate_hz = 0;
  return spec;
}

// A force or moment on the beam named "beam", at its root.
inline LoadSpec BeamLoad(LoadSpec::Kind kind, LoadSpec::Frame frame, const Vec3& vector) {
  LoadSpec load;
  load.body = "beam";
  load.kind = kind;
  load.frame = frame;
  load.vector = vector;
  return load;
}

// A dead force or moment at the tip of the beam named "beam" of the given length.
inline LoadSpec TipLoad(LoadSpec::Kind kind, const Vec3& vector, double length) {
  LoadSpec load = BeamLoad(kind, LoadSpec::Frame::kWorld, vector);
  load.p_BoP_B = Vec3(length, 0, 0);
  return load;
}

// A dead tip force on for the first `duration` seconds, then off: a kick.
inline LoadSpec TipKick(const Vec3& force, double length, double duration) {
  LoadSpec load = TipLoad(LoadSpec::Kind::kForce, force, length);
  load.scale.kind = TimeFunctionSpec::Kind::kTable;
  load.scale.times = {0.0, duration, duration + 1e-9};
  load.scale.values = {1.0, 1.0, 0.0};
  return load;
}

// A uniform load per unit length along the whole beam named "beam" [N/m or N m/m].
inline LoadSpec DistributedLoad(LoadSpec::Kind kind, LoadSpec::Frame frame, const Vec3& per_length) {
  LoadSpec load = BeamLoad(kind, frame, per_length);
  load.distributed = true;
  return load;
}

// A measured figure for RecordProperty, in scientific notation.
inline std::string Figure(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3e", value);
  return text;
}

}  // namespace test
}  // namespace flexmbd
