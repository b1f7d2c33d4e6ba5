#pragma once
/// @file
/// Writes output samples as CSV: a header row, then one row per sample. Columns: t, then per joint variable
/// joint.<name>.position/.velocity/.effort, per joint joint.<name>.reaction_force_{x,y,z} (W) and
/// joint.<name>.reaction_moment_{x,y,z} (rotational multipliers), per stop
/// stop.<joint>.<stop>.in_contact (0/1), .force [N], .torque [N m or N], .approach [m], per frictional joint
/// friction.<joint>.sticking (0/1), .torque [N m or N], .normal_force [N], .slip_velocity [m/s], .work [J],
/// per station k of output.beam_stations beam.<name>.s<k>.{N,V2,V3,T,M2,M3} (section forces and moments,
/// section frame), .{e1,g2,g3,k1,k2,k3} (axial strain, shear strains, twist and bending curvatures),
/// .{ux,uy,uz} (displacement, W) and .{rx,ry,rz} (rotation vector of R_W(s) R_W0(s)^T, W), then
/// energy.kinetic/.potential/.total/.external_work/.dissipated/.numerical_dissipation, solver.dt,
/// solver.iterations.
///
/// Every write is checked: a failed one throws OutputError, and the file keeps its whole rows (the row being
/// written is cut off), so it stays readable up to the failure.

#include <ostream>
#include <string>
#include <vector>

#include "flexmbd/io/whole_line_file_buffer.hpp"
#include "flexmbd/solver/output_sample.hpp"

namespace flexmbd {

class Model;

class CsvSink {
 public:
  /// Opens `path` for writing; throws ConfigError naming the path if it cannot.
  CsvSink(const Model& model, const std::string& path);

  /// Appends the row of `sample`. Throws OutputError naming the file, the reason and the samples it holds
  /// if writing fails; the sink writes nothing afterwards.
  void Write(const OutputSample& sample);

  /// Writes what is buffered and closes the file; throws OutputError as Write does, unless Write already
  /// did. Also done by the destructor, which cannot report a failure.
  void Close();

 private:
  [[noreturn]] void ThrowWriteError();
  /// Appends `value` (a double or an int) to the row being formed; PutField a comma and `value`.
  template <typename Number>
  void Put(Number value);
  template <typename Number>
  void PutField(Number value);

  std::string path_;
  std::vector<bool> harmonic_rotors_;  ///< per rotor: whether it has the harmonic inflow's columns
  std::vector<char> row_;              ///< the row being formed, written to the stream whole
  size_t row_length_ = 0;
  WholeLineFileBuffer file_;
  std::ostream out_;
};

}  // namespace flexmbd
