#!/usr/bin/env bash
# Builds flexmbd (Release) in a catkin workspace outside the source tree:
#   ${FLEXMBD_WS:-$HOME/flexmbd_ws}/src/flexmbd -> this repository.
# Re-running it rebuilds incrementally. Extra arguments go to catkin_make and so to ninja (e.g. a target:
# `build.sh run_tests`).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

command -v catkin_make >/dev/null 2>&1 || die "catkin_make not found; run scripts/install_deps.sh first"

[[ "${FLEXMBD_WS}" != / ]] || die "FLEXMBD_WS must not be /"
case "${FLEXMBD_WS}/" in
  "${FLEXMBD_REPO_ROOT}/"*) die "workspace ${FLEXMBD_WS} is inside the repository ${FLEXMBD_REPO_ROOT}; set FLEXMBD_WS elsewhere" ;;
esac
mkdir -p "${FLEXMBD_WS}/src" || die "cannot create workspace ${FLEXMBD_WS}"

link="${FLEXMBD_WS}/src/flexmbd"
if [[ -L "${link}" ]]; then
  previous="$(readlink "${link}")"
  if [[ "${previous}" != "${FLEXMBD_REPO_ROOT}" ]]; then
    # Object files built from another checkout may be newer than this checkout's sources and
    # would not be rebuilt: start the build over.
    echo "build: workspace was built from ${previous}; switching to ${FLEXMBD_REPO_ROOT} (full rebuild)"
    rm -rf "${FLEXMBD_WS:?}/build" "${FLEXMBD_WS:?}/devel"
    ln -sfn "${FLEXMBD_REPO_ROOT}" "${link}"
  fi
elif [[ -e "${link}" ]]; then
  die "${link} exists and is not a symlink; move it away or set FLEXMBD_WS to another directory"
else
  ln -s "${FLEXMBD_REPO_ROOT}" "${link}"
fi

# Ninja, not make: with make a target's files wait until every library it links is built, so the last batch of the
# core, then of io, then of the ROS layer compiled alone with the other core idle; ninja compiles a file as soon as
# its sources and generated headers exist. A workspace configured for make is configured again.
if [[ -f "${FLEXMBD_WS}/build/Makefile" && ! -f "${FLEXMBD_WS}/build/build.ninja" ]]; then
  echo "build: workspace ${FLEXMBD_WS} was configured for make; configuring it for ninja (full rebuild)"
  rm -rf "${FLEXMBD_WS:?}/build"
fi

echo "build: workspace ${FLEXMBD_WS} (src/flexmbd -> ${FLEXMBD_REPO_ROOT})"
cd "${FLEXMBD_WS}"
# catkin fixes the environment of the tests (build/catkin_generated/setup_cached.sh) when CMake first runs,
# with only the devel directories that exist then: the Python messages, generated later, would stay off the
# tests' PYTHONPATH. The directory is made first, and a workspace configured without it is configured again.
python_devel="${FLEXMBD_WS}/devel/lib/python3/dist-packages"
cached_setup="${FLEXMBD_WS}/build/catkin_generated/setup_cached.sh"
force_cmake=()
if [[ -f "${cached_setup}" ]] && ! grep -q "${python_devel}" "${cached_setup}"; then
  force_cmake=(--force-cmake)
fi
mkdir -p "${python_devel}" || die "cannot create ${python_devel}"
# -j4: CMakeLists.txt's job pool keeps compiles and links at two; the other two slots run the message generators
# (short Python scripts that the ROS layer waits for) beside them. With -j2 they ran one at a time beside a single
# compile once the core's batches were done: a minute of one idle core on a loaded machine.
if ! catkin_make --use-ninja "${force_cmake[@]}" -DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3 -j4 "$@" </dev/null; then
  die "catkin_make $* failed in ${FLEXMBD_WS} (see the compiler output above)"
fi
echo "build: done (${FLEXMBD_WS}/devel)"
