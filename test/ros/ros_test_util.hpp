#pragma once
// Helpers shared by the test/ros tests (the node's library, without a master); SourcePath and RunRunner
// come from the integration tests' helpers.

#include <string>

#include "../integration/helpers/runner.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/model/model.hpp"

namespace flexmbd {
namespace test {

/// The reference case config/double_pendulum/: shoulder at (0, 0, 2) m turning about y, driven from 0 deg;
/// elbow 1 m further along link1, starting at -30 deg.
inline Model DoublePendulum() {
  return BuildModel(LoadModelSpec(SourcePath("config/double_pendulum/double_pendulum.urdf"),
                                  SourcePath("config/double_pendulum/double_pendulum.yaml")));
}

}  // namespace test
}  // namespace flexmbd
