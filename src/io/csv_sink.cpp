#include "flexmbd/io/csv_sink.hpp"

#include <charconv>

#include "flexmbd/common/error.hpp"
#include "flexmbd/model/model.hpp"

namespace flexmbd {
namespace {
// Column suffixes of one beam station, in BeamStationSample order (load, strain, displacement, rotation).
const char* const kStationColumns[18] = {"N",  "V2", "V3", "T",  "M2", "M3", "e1", "g2", "g3",
                                         "k1", "k2", "k3", "ux", "uy", "uz", "rx", "ry", "rz"};

// The shortest text that reads back as the same double: a stream's max_digits10 formatting took 9% of a 200 s
// published-antenna run (4,001 rows of 115 columns), std::to_chars a fraction of that.
void PutNumber(std::ostream& out, double value) {
  char text[32];
  const char* end = std::to_chars(text, text + sizeof text, value).ptr;
  out.write(text, end - text);
}

void PutField(std::ostream& out, double value) {
  out.put(',');
  PutNumber(out, value);
}
}  // namespace

CsvSink::CsvSink(const Model& model, const std::string& path) : path_(path), file_(path), out_(&file_) {
  if (!file_.is_open()) {
    throw ConfigError("output.csv: cannot open '" + path + "' for writing (" + file_.error() +
                      "); expected a writable file path");
  }
  out_ << "t";
  for (const std::string& name : model.variable_names()) {
    out_ << ",joint." << name << ".position,joint." << name << ".velocity,joint." << name << ".effort";
  }
  for (const Joint* joint : model.joints()) {
    for (const char* axis : {"x", "y", "z"}) out_ << ",joint." << joint->name() << ".reaction_force_" << axis;
    for (const char* axis : {"x", "y", "z"}) out_ << ",joint." << joint->name() << ".reaction_moment_" << axis;
  }
  for (const StopInfo& stop : model.stops()) {
    for (const char* column : {"in_contact", "force", "torque", "approach"}) {
      out_ << ",stop." << stop.joint << '.' << stop.stop << '.' << column;
    }
  }
  for (const FrictionInfo& friction : model.frictions()) {
    for (const char* column : {"sticking", "torque", "normal_force", "slip_velocity", "work"}) {
      out_ << ",friction." << friction.joint << '.' << column;
    }
  }
  for (const BeamStationInfo& station : model.beam_stations()) {
    for (const char* column : kStationColumns) {
      out_ << ",beam." << station.beam << ".s" << station.index << "." << column;
    }
  }
  for (const TypicalSectionAero* section : model.aero_sections()) {
    for (const char* column : {"lift", "moment", "hinge_moment"}) out_ << ",aero." << section->name() << '.' << column;
    for (int k = 0; k < section->num_states(); ++k) out_ << ",aero." << section->name() << '.' << section->StateName(k);
  }
  for (const StripStationInfo& station : model.strip_stations()) {
    const std::string prefix = ",strip." + station.strip + ".s" + std::to_string(station.index) + ".";
    for (const char* column : {"lift", "moment", "hinge_moment"}) out_ << prefix << column;
    for (int k = 0; k < station.inner->num_states(); ++k) out_ << prefix << station.inner->StateName(k);
  }
  for (const RotorInflow* rotor : model.aero_rotors()) {
    out_ << ",aero." << rotor->name() << ".inflow,aero." << rotor->name() << ".thrust";
    harmonic_rotors_.push_back(rotor->harmonic());
    if (!rotor->harmonic()) continue;
    for (const char* column : {"inflow_cos", "inflow_sin", "moment_cos", "moment_sin"}) {
      out_ << ",aero." << rotor->name() << '.' << column;
    }
  }
  out_ << ",energy.kinetic,energy.potential,energy.total,energy.external_work,energy.dissipated,"
          "energy.numerical_dissipation,solver.dt,solver.iterations\n";
  if (!out_) ThrowWriteError();
}

void CsvSink::Write(const OutputSample& s) {
  PutNumber(out_, s.t);
  for (int k = 0; k < s.position.size(); ++k) {
    for (double value : {s.position[k], s.velocity[k], s.effort[k]}) PutField(out_, value);
  }
  for (size_t k = 0; k < s.reaction_force_W.size(); ++k) {
    for (int axis = 0; axis < 3; ++axis) PutField(out_, s.reaction_force_W[k][axis]);
    for (int axis = 0; axis < 3; ++axis) PutField(out_, s.reaction_moment[k][axis]);
  }
  for (const StopSample& stop : s.stops) {
    out_ << ',' << stop.in_contact;
    for (double value : {stop.force, stop.torque, stop.approach}) PutField(out_, value);
  }
  for (const FrictionSample& f : s.friction) {
    out_ << ',' << f.sticking;
    for (double value : {f.torque, f.normal_force, f.slip_velocity, f.work}) PutField(out_, value);
  }
  for (const BeamStationSample& b : s.beam_stations) {
    for (int k = 0; k < 6; ++k) PutField(out_, b.load[k]);
    for (int k = 0; k < 6; ++k) PutField(out_, b.strain[k]);
    for (int k = 0; k < 3; ++k) PutField(out_, b.displacement[k]);
    for (int k = 0; k < 3; ++k) PutField(out_, b.rotation[k]);
  }
  for (const std::vector<AeroSectionSample>* aero : {&s.aero_sections, &s.strip_stations}) {
    for (const AeroSectionSample& a : *aero) {
      for (double value : {a.lift, a.moment, a.hinge_moment}) PutField(out_, value);
      for (int k = 0; k < a.inflow.size(); ++k) PutField(out_, a.inflow[k]);
    }
  }
  for (size_t k = 0; k < s.aero_rotors.size(); ++k) {
    const AeroRotorSample& rotor = s.aero_rotors[k];
    for (double value : {rotor.inflow, rotor.thrust}) PutField(out_, value);
    if (!harmonic_rotors_[k]) continue;
    for (double value : {rotor.inflow_cos, rotor.inflow_sin, rotor.moment_cos, rotor.moment_sin}) PutField(out_, value);
  }
  for (double value :
       {s.kinetic, s.potential, s.total(), s.external_work, s.dissipated, s.numerical_dissipation, s.dt}) {
    PutField(out_, value);
  }
  out_ << ',' << s.iterations << '\n';
  if (!out_) ThrowWriteError();
}

void CsvSink::Close() {
  // a stream already bad has thrown from Write (or from an earlier Close)
  if (!file_.Close() && out_.good()) ThrowWriteError();
}

void CsvSink::ThrowWriteError() {
  out_.setstate(std::ios::badbit);
  const long rows = file_.lines_written();
  const std::string holds = rows == 0   ? "nothing"
                            : rows == 1 ? "its header row and no sample"
                                        : "its header row and the first " + std::to_string(rows - 1) + " samples";
  throw OutputError("output.csv: writing '" + path_ + "' failed (" + file_.error() + "); the file holds " + holds);
}

}  // namespace flexmbd
