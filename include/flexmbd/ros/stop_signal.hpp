#pragma once
/// @file
/// SIGINT and SIGTERM as a request to stop the run: the loop then records what it computed, closes the
/// files and logs before ROS shuts down (roscpp's own SIGINT handler would shut rosconsole down first).

namespace flexmbd {
namespace ros {

/// Installs the handlers: in the node after ros::init with ros::init_options::NoSigintHandler; in the runner
/// before its run (Simulation::StopWhen polls StopRequested).
void InstallStopHandlers();

/// True once SIGINT or SIGTERM has arrived.
bool StopRequested();

}  // namespace ros
}  // namespace flexmbd
