#!/usr/bin/env bash
# Installs the Debian 12 packages flexmbd needs to build, test, run and plot.
# Idempotent: when everything is installed it only checks and exits.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

PACKAGES=(
  # ROS 1 (Debian's own packaging: no /opt/ros, catkin lives in /usr)
  ros-base-dev libroscpp-dev librosbag-dev librostest-dev
  python3-rostest python3-roslaunch python3-rosmaster python3-rosbag python3-rospy rosout
  catkin python3-catkin-pkg ros-message-generation ros-message-runtime
  ros-std-msgs libstd-msgs-dev ros-sensor-msgs libsensor-msgs-dev ros-geometry-msgs libgeometry-msgs-dev
  ros-std-srvs libstd-srvs-dev
  # messages of the node's topics: /tf, ~markers, /clock
  ros-tf2-msgs libtf2-msgs-dev ros-visualization-msgs libvisualization-msgs-dev
  ros-rosgraph-msgs libros-rosgraph-msgs-dev
  # the same messages for Python clients, and the command-line tools (rostopic, rosservice, rosrun)
  python3-std-msgs python3-sensor-msgs python3-geometry-msgs python3-std-srvs python3-tf2-msgs
  python3-visualization-msgs python3-rosgraph-msgs python3-genpy python3-rostopic python3-rosservice rosbash
  # tf2_ros lookups of the node's frames (test/integration/python/tf_tree.py, and users' clients)
  python3-tf2-ros
  # core and io libraries
  liburdfdom-dev libeigen3-dev libsuitesparse-dev libyaml-cpp-dev
  # tests and benchmarks
  libgtest-dev libbenchmark-dev
  # plotting
  python3-matplotlib python3-numpy
  # parameter sweeps as Slurm job arrays (scripts/sweep.py --slurm), and the single-node Slurm of its test
  slurm-client slurmctld slurmd munge
  # toolchain
  cmake g++ make ninja-build
)

missing=()
for pkg in "${PACKAGES[@]}"; do
  status="$(dpkg-query -W -f='${db:Status-Status}' "${pkg}" 2>/dev/null || true)"
  if [[ "${status}" != "installed" ]]; then
    missing+=("${pkg}")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "install_deps: all ${#PACKAGES[@]} required packages are installed"
  exit 0
fi

echo "install_deps: missing packages: ${missing[*]}"

if [[ "$(id -u)" -eq 0 ]]; then
  SUDO=()
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
  SUDO=(sudo -n)
else
  die "not root and no password-less sudo; install as root: apt-get install ${missing[*]}"
fi

export DEBIAN_FRONTEND=noninteractive
APT_OPTS=(-y -q -o Dpkg::Options::=--force-confdef -o Dpkg::Options::=--force-confold)

"${SUDO[@]}" apt-get update -q </dev/null ||
  die "apt-get update failed"
"${SUDO[@]}" apt-get install "${APT_OPTS[@]}" --no-install-recommends "${missing[@]}" </dev/null ||
  die "apt-get install failed for: ${missing[*]}"

echo "install_deps: installed ${missing[*]}"
