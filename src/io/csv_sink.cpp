#include "flexmbd/io/csv_sink.hpp"

#include <charconv>

#include "flexmbd/common/error.hpp"
#include "flexmbd/model/model.hpp"

namespace flexmbd {
namespace {
// Column suffixes of one beam station, in BeamStationSample order (load, strain, displacement, rotation).
const char* const kStationColumns[18] = {"N",  "V2", "V3", "T",  "M2", "M3", "e1", "g2", "g3",
                                         "k1", "k2", "k3", "ux", "uy", "uz", "rx", "ry", "rz"};

// Room kept for one number: the shortest text of a double that reads back as the same double has at most 24
// characters (as "-2.2250738585072014e-308"), an int 11; what is left after it takes the next comma or the '\n'.
constexpr size_t kNumberRoom = 32;
}  // namespace

// The shortest text that reads back as the same double: a stream's max_digits10 formatting took 9% of a 200 s
// published-antenna run (4,001 rows of 115 columns), std::to_chars a fraction of that. Fields are formed in the
// row's buffer and the row goes to the stream at once: a stream write per field (its sentry, its checks) cost
// about as much as the formatting.
template <typename Number>
void CsvSink::Put(Number value) {
  if (row_.size() - row_length_ < kNumberRoom) row_.resize(2 * row_.size());
  row_length_ = std::to_chars(row_.data() + row_length_, row_.data() + row_.size(), value).ptr - row_.data();
}

template <typename Number>
void CsvSink::PutField(Number value) {
  row_[row_length_++] = ',';
  Put(value);
}

CsvSink::CsvSink(const Model& model, const std::string& path)
    : path_(path), row_(4096), file_(path), out_(&file_) {
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
  row_length_ = 0;
  Put(s.t);
  for (int k = 0; k < s.position.size(); ++k) {
    for (double value : {s.position[k], s.velocity[k], s.effort[k]}) PutField(value);
  }
  for (size_t k = 0; k < s.reaction_force_W.size(); ++k) {
    for (int axis = 0; axis < 3; ++axis) PutField(s.reaction_force_W[k][axis]);
    for (int axis = 0; axis < 3; ++axis) PutField(s.reaction_moment[k][axis]);
  }
  for (const StopSample& stop : s.stops) {
    PutField(static_cast<int>(stop.in_contact));
    for (double value : {stop.force, stop.torque, stop.approach}) PutField(value);
  }
  for (const FrictionSample& f : s.friction) {
    PutField(static_cast<int>(f.sticking));
    for (double value : {f.torque, f.normal_force, f.slip_velocity, f.work}) PutField(value);
  }
  for (const BeamStationSample& b : s.beam_stations) {
    for (int k = 0; k < 6; ++k) PutField(b.load[k]);
    for (int k = 0; k < 6; ++k) PutField(b.strain[k]);
    for (int k = 0; k < 3; ++k) PutField(b.displacement[k]);
    for (int k = 0; k < 3; ++k) PutField(b.rotation[k]);
  }
  for (const std::vector<AeroSectionSample>* aero : {&s.aero_sections, &s.strip_stations}) {
    for (const AeroSectionSample& a : *aero) {
      for (double value : {a.lift, a.moment, a.hinge_moment}) PutField(value);
      for (int k = 0; k < a.inflow.size(); ++k) PutField(a.inflow[k]);
    }
  }
  for (size_t k = 0; k < s.aero_rotors.size(); ++k) {
    const AeroRotorSample& rotor = s.aero_rotors[k];
    for (double value : {rotor.inflow, rotor.thrust}) PutField(value);
    if (!harmonic_rotors_[k]) continue;
    for (double value : {rotor.inflow_cos, rotor.inflow_sin, rotor.moment_cos, rotor.moment_sin}) PutField(value);
  }
  for (double value :
       {s.kinetic, s.potential, s.total(), s.external_work, s.dissipated, s.numerical_dissipation, s.dt}) {
    PutField(value);
  }
  PutField(s.iterations);
  row_[row_length_++] = '\n';
  out_.write(row_.data(), static_cast<std::streamsize>(row_length_));
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
