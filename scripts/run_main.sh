#!/usr/bin/env bash
# The main job: installs what is missing, builds flexmbd, runs the main case with the ROS node through its
# launch file (roslaunch starts a roscore if none is running) recording every sample to a bag, and plots the
# bag to PNG files beside it. Ends on its own: the node exits at the end of the run and takes roslaunch down.
#   FLEXMBD_CASE  case name: config/<case>/ and launch/<case>.launch (default: antenna_published, its case 1)
#   FLEXMBD_OUT   output folder (default: ./flexmbd_output, relative to the current directory)
#   FLEXMBD_WS    catkin workspace (default: $HOME/flexmbd_ws)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
scripts="${FLEXMBD_REPO_ROOT}/scripts"

case_name="${FLEXMBD_CASE:-antenna_published}"
launch_file="${FLEXMBD_REPO_ROOT}/launch/${case_name}.launch"
if [[ ! -f "${launch_file}" ]]; then
  available="$(cd "${FLEXMBD_REPO_ROOT}/launch" 2>/dev/null && ls -- *.launch 2>/dev/null |
    sed 's/\.launch$//' | paste -sd ' ' || true)"
  die "case '${case_name}': missing ${launch_file} (cases with a launch file: ${available:-none})"
fi

mkdir -p "${FLEXMBD_OUT:-flexmbd_output}" || die "cannot create output folder ${FLEXMBD_OUT:-flexmbd_output}"
out_dir="$(cd "${FLEXMBD_OUT:-flexmbd_output}" && pwd -P)"

bash "${scripts}/install_deps.sh"
bash "${scripts}/build.sh"

# catkin's setup script reads variables that may be unset
set +u
source "${FLEXMBD_WS}/devel/setup.bash" || die "cannot source ${FLEXMBD_WS}/devel/setup.bash"
set -u

bag="${out_dir}/${case_name}.bag"
launch_log="${out_dir}/${case_name}_roslaunch.log"
# The one place that launches the main case: as fast as the solver goes, every sample to the bag.
main_command=(roslaunch flexmbd "${case_name}.launch" "bag:=${bag}" real_time_factor:=0)

echo "run_main: ${main_command[*]}"
rm -f "${bag}" "${out_dir}/${case_name}"_*.png
launch_status=0
"${main_command[@]}" </dev/null 2>&1 | tee "${launch_log}" || launch_status=$?
# roslaunch exits 0 when its required node ends, whatever the node's status: read it from the log.
node_failed=0
if ((launch_status != 0)) || grep -q "process has died \[pid [0-9]*, exit code [1-9]" "${launch_log}"; then
  node_failed=1
fi
plot=(/usr/bin/python3 "${scripts}/plot_bag.py" "${bag}" --out-dir "${out_dir}")

if ((node_failed)); then
  # The node closes its bag on failure: plot what it computed, then report the failure.
  if [[ -s "${bag}" ]] && "${plot[@]}" 2>/dev/null; then
    die "case '${case_name}' failed (see ${launch_log}); partial output plotted in ${out_dir}"
  fi
  die "case '${case_name}' failed (see ${launch_log}); no plottable output"
fi
[[ -s "${bag}" ]] || die "case '${case_name}' wrote no bag at ${bag} (see ${launch_log})"
rosbag info "${bag}"
echo "run_main: plotting ${bag}"
"${plot[@]}" || die "plotting ${bag} failed"
echo "run_main: outputs in ${out_dir}"
