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

#include <fstream>
#include <string>

#include "flexmbd/solver/output_sample.hpp"

namespace flexmbd {

class Model;

class CsvSink {
 public:
  /// Opens `path` for writing; throws ConfigError naming the path if it cannot.
  CsvSink(const Model& model, const std::string& path);

  void Write(const OutputSample& sample);

  /// Flushes and closes; also done by the destructor.
  void Close();

 private:
  std::ofstream out_;
};

}  // namespace flexmbd
