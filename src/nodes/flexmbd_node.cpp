// flexmbd_node: runs a case from the parameter server and publishes its samples (docs/ros.md).
// Exit status: 0 success (or stopped by SIGINT / SIGTERM), 2 bad input (the message names the file or
// parameter), 3 the run failed (solver failure, or an output file that cannot be written), 4 an unexpected
// error (a bug). Each failure is one [FATAL] line.

#include <ros/ros.h>

#include "flexmbd/common/error.hpp"
#include "flexmbd/ros/simulator_node.hpp"
#include "flexmbd/ros/stop_signal.hpp"

int main(int argc, char** argv) {
  ::ros::init(argc, argv, "flexmbd", ::ros::init_options::NoSigintHandler);
  flexmbd::ros::InstallStopHandlers();
  // the handles keep ROS (and rosconsole) up until the error messages below are out
  ::ros::NodeHandle node, private_node("~");
  try {
    flexmbd::ros::SimulatorNode simulator(node, private_node);
    return simulator.Run();
  } catch (const flexmbd::ConfigError& error) {
    ROS_FATAL_STREAM(error.what());
    return flexmbd::kExitBadInput;
  } catch (const flexmbd::OutputError& error) {  // e.g. a bag on a full disk, found while opening or closing
    ROS_FATAL_STREAM("flexmbd: " << error.what());
    return flexmbd::kExitRunFailed;
  } catch (const std::exception& error) {
    ROS_FATAL_STREAM("flexmbd: internal error: " << error.what());
    return flexmbd::kExitInternalError;
  } catch (...) {
    ROS_FATAL_STREAM("flexmbd: internal error: an exception of unknown type");
    return flexmbd::kExitInternalError;
  }
}
