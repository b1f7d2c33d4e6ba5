#pragma once
/// @file
/// Writes output samples as CSV: a header row, then one row per sample. Columns: t, then per joint variable
/// joint.<name>.position/.velocity/.effort, per joint joint.<name>.reaction_force_{x,y,z} (W) and
/// joint.<name>.reaction_moment_{x,y,z} (rotational multipliers), per stop
/// stop.<joint>.<stop>.in_contact (0/1), .force [N], .torque [N m or N], .approach [m], per frictional joint
/// friction.<joint>.sticking (0/1), .torque [N m or N], .normal_force [N], .slip_velocity [m/s], .work [J], then
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
