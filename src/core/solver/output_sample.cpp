#include "flexmbd/solver/output_sample.hpp"

#include "flexmbd/model/model.hpp"

namespace flexmbd {
namespace {
// The station's section at a state that the step `ctx` led to, with the structural damping that step applied.
BeamStationSample SampleStation(const Model& model, const State& state, const StepContext& ctx,
                                const BeamStationInfo& station) {
  const BeamElement::Section now = station.element->SectionAt(state, station.s_element);
  const BeamElement::Section initial = station.element->SectionAt(model.initial_state(), station.s_element);
  BeamStationSample sample;
  sample.load = now.load + station.element->DampingLoadAt(ctx, station.s_element);
  sample.strain = now.strain;
  sample.displacement = now.x - initial.x;
  sample.velocity = now.v;
  sample.rotation = Log(now.R * initial.R.transpose());
  return sample;
}

// The loads [lift, moment, hinge moment] of an aero element (a typical section's, or a strip's per unit span) and
// its inflow states.
AeroSectionSample AeroSample(const Vec3& loads, const Element& element, const State& state) {
  AeroSectionSample sample;
  sample.lift = loads[0];
  sample.moment = loads[1];
  sample.hinge_moment = loads[2];
  sample.inflow = state.element_states.segment(element.first_state(), element.num_states());
  return sample;
}

AeroSectionSample SampleAero(const TypicalSectionAero& section, const State& state, const StepContext& ctx) {
  return AeroSample(section.SectionLoads(ctx), section, state);
}

// One strip's loads per unit span and its states.
AeroSectionSample SampleStrip(const BeamStripAero& strip, const State& state, const StepContext& ctx) {
  return AeroSample(strip.StripLoads(ctx) / strip.length(), strip, state);
}

// The cubic through positions x_a, x_b with rates v_a, v_b at the ends of an interval of length `span`, at the
// fraction u of it. A step of the trapezoidal family has x_b - x_a = span (v_a + v_b) / 2 (T3), for which the cubic
// is the quadratic of constant acceleration (v_b - v_a) / span: on a uniform turn it errs by O(h^4), where the chord
// between the ends cut a spinning blade's tip inwards by R (Omega h)^2 / 8, and a joint variable's samples carried up
// to h^2 |q''| / 8 (docs/theory.md, "Against the aim of the default tolerance").
template <typename Vector>
Vector HermiteAt(const Vector& x_a, const Vector& v_a, const Vector& x_b, const Vector& v_b, double span, double u) {
  const double u2 = u * u, u3 = u2 * u;
  return ((2.0 * u3 - 3.0 * u2 + 1.0) * x_a + (u3 - 2.0 * u2 + u) * span * v_a + (3.0 * u2 - 2.0 * u3) * x_b +
          (u3 - u2) * span * v_b)
      .eval();
}

AeroSectionSample Mix(const AeroSectionSample& x, const AeroSectionSample& y, double u) {
  AeroSectionSample z;
  z.lift = (1.0 - u) * x.lift + u * y.lift;
  z.moment = (1.0 - u) * x.moment + u * y.moment;
  z.hinge_moment = (1.0 - u) * x.hinge_moment + u * y.hinge_moment;
  z.inflow = (1.0 - u) * x.inflow + u * y.inflow;
  return z;
}
}  // namespace

EnergyTally StateEnergy(const Model& model, const State& state) {
  EnergyTally energy;
  for (const auto& element : model.elements()) element->AddEnergy(state, model.solver().gravity, &energy);
  return energy;
}

OutputSample MakeSample(const Model& model, const State& state, const StepContext& ctx, double dt, int iterations) {
  OutputSample s;
  s.t = state.t;
  s.position = state.q;
  s.velocity = state.qdot;
  s.effort = Eigen::VectorXd::Zero(model.num_variables());
  for (const Joint* joint : model.joints()) {
    if (joint->num_variables() > 0) {
      s.effort.segment(joint->first_variable(), joint->num_variables()) = joint->VariableForces(ctx);
    }
    const Eigen::VectorXd lambda = state.lambda.segment(joint->first_multiplier(), joint->num_constraints());
    s.reaction_force_W.push_back(-lambda.head<3>());
    s.reaction_moment.push_back(joint->num_constraints() == 6 ? Vec3(-lambda.tail<3>()) : Vec3::Zero());
  }
  for (const JointStop* stop : model.stop_effects()) s.stops.push_back(stop->Sample(state, ctx));
  for (const FrictionEffect* friction : model.friction_effects()) s.friction.push_back(friction->Sample(state, ctx));
  const EnergyTally energy = StateEnergy(model, state);
  s.kinetic = energy.kinetic;
  s.potential = energy.potential;
  s.external_work = state.external_work;
  s.dissipated = state.dissipated_physical;
  s.numerical_dissipation = state.dissipated_numerical;
  for (const BeamStationInfo& station : model.beam_stations()) {
    s.beam_stations.push_back(SampleStation(model, state, ctx, station));
  }
  for (const TypicalSectionAero* section : model.aero_sections()) {
    s.aero_sections.push_back(SampleAero(*section, state, ctx));
  }
  for (const StripStationInfo& station : model.strip_stations()) {
    // A station at a node (weight 0) takes that node's strip alone.
    const AeroSectionSample inner = SampleStrip(*station.inner, state, ctx);
    const bool between = station.weight > 0.0;
    s.strip_stations.push_back(between ? Mix(inner, SampleStrip(*station.outer, state, ctx), station.weight) : inner);
  }
  for (const RotorInflow* rotor : model.aero_rotors()) {
    const Eigen::Vector3d loads = rotor->Loads(ctx);
    AeroRotorSample sample{state.element_states[rotor->first_state()], loads[0]};
    if (rotor->harmonic()) {
      sample.inflow_cos = state.element_states[rotor->first_state() + 1];
      sample.inflow_sin = state.element_states[rotor->first_state() + 2];
      sample.moment_cos = loads[1];
      sample.moment_sin = loads[2];
    }
    s.aero_rotors.push_back(sample);
  }
  s.dt = dt;
  s.iterations = iterations;
  return s;
}

void MixLinearQuantities(const OutputSample& a, const OutputSample& b, double u, OutputSample* s) {
  auto mix = [u](const auto& x, const auto& y) { return ((1.0 - u) * x + u * y).eval(); };
  auto blend = [u](double x, double y) { return (1.0 - u) * x + u * y; };
  s->velocity = mix(a.velocity, b.velocity);
  s->effort = mix(a.effort, b.effort);
  for (size_t k = 0; k < s->reaction_force_W.size(); ++k) {
    s->reaction_force_W[k] = mix(a.reaction_force_W[k], b.reaction_force_W[k]);
    s->reaction_moment[k] = mix(a.reaction_moment[k], b.reaction_moment[k]);
  }
  s->kinetic = blend(a.kinetic, b.kinetic);
  s->potential = blend(a.potential, b.potential);
  s->external_work = blend(a.external_work, b.external_work);
  s->dissipated = blend(a.dissipated, b.dissipated);
  s->numerical_dissipation = blend(a.numerical_dissipation, b.numerical_dissipation);
  for (size_t k = 0; k < s->beam_stations.size(); ++k) {
    const BeamStationSample &x = a.beam_stations[k], &y = b.beam_stations[k];
    BeamStationSample& z = s->beam_stations[k];
    z.load = mix(x.load, y.load);
    z.strain = mix(x.strain, y.strain);
    z.velocity = mix(x.velocity, y.velocity);
  }
  for (size_t k = 0; k < s->aero_sections.size(); ++k) {
    s->aero_sections[k] = Mix(a.aero_sections[k], b.aero_sections[k], u);
  }
  for (size_t k = 0; k < s->strip_stations.size(); ++k) {
    s->strip_stations[k] = Mix(a.strip_stations[k], b.strip_stations[k], u);
  }
  for (size_t k = 0; k < s->aero_rotors.size(); ++k) {
    const AeroRotorSample &x = a.aero_rotors[k], &y = b.aero_rotors[k];
    s->aero_rotors[k] = {blend(x.inflow, y.inflow),         blend(x.thrust, y.thrust),
                         blend(x.inflow_cos, y.inflow_cos), blend(x.inflow_sin, y.inflow_sin),
                         blend(x.moment_cos, y.moment_cos), blend(x.moment_sin, y.moment_sin)};
  }
}

OutputSample Interpolate(const OutputSample& a, const OutputSample& b, double t) {
  const double span = b.t - a.t;
  const double u = span > 0 ? (t - a.t) / span : 1.0;
  auto blend = [u](double x, double y) { return (1.0 - u) * x + u * y; };
  OutputSample s = b;
  s.t = t;
  MixLinearQuantities(a, b, u, &s);
  s.position = HermiteAt(a.position, a.velocity, b.position, b.velocity, span, u);
  // Contacts are events, not smooth signals: the nearer sample's records stand.
  if (u < 0.5) s.stops = a.stops;
  // Inside a step friction has the step's forces (b's), and the mode they belong to: stuck where the step held the
  // joint by its sticking row, or where it is stuck at both ends (held by a stop, (F7)). A capture step begins
  // sliding, yet its force is the sticking multiplier, the mean of the kinetic force until the slip stops and of the
  // holding force after (F3), which the step does not separate: its samples are stuck, as its solution is, at the
  // slip speed of at most 2 v0 that the capture allows (F2). Labelled sliding, they showed that force below mu_k rho N.
  if (u < 1.0) {
    for (size_t k = 0; k < s.friction.size(); ++k) {
      const FrictionSample &x = a.friction[k], &y = b.friction[k];
      FrictionSample& z = s.friction[k];
      z.sticking = y.step_stuck || (x.sticking && y.sticking);
      z.slip_velocity = blend(x.slip_velocity, y.slip_velocity);
      z.work = blend(x.work, y.work);
    }
  }
  for (size_t k = 0; k < s.beam_stations.size(); ++k) {
    const BeamStationSample &x = a.beam_stations[k], &y = b.beam_stations[k];
    BeamStationSample& z = s.beam_stations[k];
    z.displacement = HermiteAt(x.displacement, x.velocity, y.displacement, y.velocity, span, u);
    // Linear in the rotation vector crossed its +-pi branch cut between the samples (a spinning blade read ~0 for pi).
    const Mat3 R_a = Exp(x.rotation);
    z.rotation = Log(Exp(u * Log(Exp(y.rotation) * R_a.transpose())) * R_a);
  }
  return s;
}

}  // namespace flexmbd
