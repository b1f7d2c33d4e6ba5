#pragma once
// Hand-written ModelSpecs shared by the verification tests (no files involved, so the tests check the core
// alone).

#include <algorithm>
#include <cmath>
#include <string>

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {
namespace test {

// A body of mass m with centre of mass at distance `arm` along its x axis and isotropic inertia i_cm.
inline BodySpec ArmBody(const std::string& name, double m, double arm, double i_cm) {
  BodySpec b;
  b.name = name;
  b.mass = m;
  b.inertia_cm_B = i_cm * Mat3::Identity();
  b.p_BoBcm_B = Vec3(arm, 0, 0);
  return b;
}

// A revolute joint about y between parent (empty = world) and child, at p_PJ in the parent frame.
inline JointSpec RevoluteY(const std::string& name, const std::string& parent, const std::string& child,
                           const Vec3& p_PJ) {
  JointSpec j;
  j.name = name;
  j.type = JointType::kRevolute;
  j.parent = parent;
  j.child = child;
  j.p_PJ = p_PJ;
  j.axis_J = Vec3::UnitY();
  j.effects.resize(1);
  return j;
}

// Pendulum: arm along +x at q = 0 (horizontal), pivot at the origin, gravity -z, released from rest.
inline ModelSpec Pendulum(double m, double arm, double i_cm) {
  ModelSpec spec;
  spec.source = "pendulum (test)";
  spec.bodies.push_back(ArmBody("link", m, arm, i_cm));
  spec.joints.push_back(RevoluteY("pivot", "", "link", Vec3::Zero()));
  spec.solver.gravity = Vec3(0, 0, -9.81);
  spec.solver.adaptive = false;
  spec.output.rate_hz = 0;
  return spec;
}

// Double pendulum with both arms horizontal at q = 0; link 2 hangs from the end of link 1 (x = 2 arm1).
inline ModelSpec DoublePendulum(double m, double arm, double i_cm) {
  ModelSpec spec = Pendulum(m, arm, i_cm);
  spec.source = "double pendulum (test)";
  BodySpec second = ArmBody("link2", m, arm, i_cm);
  second.p_WB = Vec3(2 * arm, 0, 0);
  spec.bodies.push_back(second);
  spec.joints.push_back(RevoluteY("elbow", "link", "link2", Vec3(2 * arm, 0, 0)));
  return spec;
}

// Mass-spring: a body of mass m on a prismatic joint along x with a spring k, released from x = amplitude at
// rest (x = A cos(w t), w = sqrt(k/m)); gravity is across the slide. Fixed step dt up to t_end, tol 1e-12.
inline ModelSpec MassSpring(double m, double k, double amplitude, SolverSpec::Integrator integrator, double dt,
                            double t_end) {
  ModelSpec spec;
  spec.source = "mass-spring (test)";
  BodySpec body = ArmBody("mass", m, 0.0, 0.01);
  body.p_WB = Vec3(amplitude, 0, 0);
  spec.bodies.push_back(body);
  JointSpec joint;
  joint.name = "slider";
  joint.type = JointType::kPrismatic;
  joint.child = "mass";
  joint.axis_J = Vec3::UnitX();
  joint.initial_position = {amplitude};
  joint.effects.resize(1);
  joint.effects[0].springs.push_back({k, 0.0});
  spec.joints.push_back(joint);
  spec.solver.gravity = Vec3(0, 0, -9.81);
  spec.solver.integrator = integrator;
  spec.solver.adaptive = false;
  spec.solver.dt = dt;
  spec.solver.dt_max = std::max(dt, spec.solver.dt_max);
  spec.solver.t_end = t_end;
  spec.solver.tol = 1.0e-12;
  spec.output.rate_hz = 0;
  return spec;
}

// A mass m on a prismatic joint along x starting at x = 0 with speed v0, no spring; gravity across the slide.
// Energy-preserving scheme, adaptive steps, every step sampled.
inline ModelSpec Slider(double m, double v0, double t_end) {
  ModelSpec spec = MassSpring(m, 0.0, 0.0, SolverSpec::Integrator::kEnergyPreserving, 1.0e-3, t_end);
  spec.source = "slider (test)";
  spec.joints[0].effects[0].springs.clear();
  spec.joints[0].initial_velocity = {v0};
  spec.bodies[0].v_WBo_W = Vec3(v0, 0, 0);
  spec.solver.adaptive = true;
  spec.solver.dt_max = 1.0e-2;
  return spec;
}

// A rotor of isotropic inertia j about its centre of mass on a revolute joint about y at the origin, spinning
// at omega0; gravity acts through the axis and does no work. Energy-preserving scheme, adaptive steps.
inline ModelSpec Rotor(double j, double omega0, double t_end) {
  ModelSpec spec = Pendulum(1.0, 0.0, j);
  spec.source = "rotor (test)";
  spec.joints[0].initial_velocity = {omega0};
  spec.bodies[0].w_WB_W = Vec3(0, omega0, 0);
  spec.solver.integrator = SolverSpec::Integrator::kEnergyPreserving;
  spec.solver.adaptive = true;
  spec.solver.dt = 1.0e-3;
  spec.solver.dt_max = 1.0e-2;
  spec.solver.t_end = t_end;
  spec.solver.tol = 1.0e-12;
  return spec;
}

// A stop on variable 0 of joint 0.
inline StopSpec Stop(StopSpec::Side side, double limit, double radius) {
  StopSpec stop;
  stop.side = side;
  stop.limit = limit;
  stop.radius = radius;
  stop.name = side == StopSpec::Side::kLower ? "lower" : "upper";
  return stop;
}

}  // namespace test
}  // namespace flexmbd
