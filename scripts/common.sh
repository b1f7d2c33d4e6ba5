# Sourced by the scripts in this folder; not meant to be run on its own.
# Sets PATH, FLEXMBD_REPO_ROOT, FLEXMBD_WS and the die helper.

# Debian's catkin needs /usr/bin/python3 (with catkin_pkg); a pyenv or venv python3 found first on
# PATH makes catkin fail with "No module named catkin_pkg".
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:${PATH}"

FLEXMBD_REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd -P)"
export FLEXMBD_REPO_ROOT

# Catkin workspace, outside the source tree.
FLEXMBD_WS="$(realpath -m -- "${FLEXMBD_WS:-${HOME:-/root}/flexmbd_ws}")"
export FLEXMBD_WS

die() {
  echo "error: $(basename "$0"): $*" >&2
  exit 1
}
