#!/usr/bin/env bash
# The main job: installs what is missing, builds flexmbd, runs the main case with the
# command-line runner and plots its CSV output to PNG files beside it.
#   FLEXMBD_CASE  case name, a folder under config/ (default: double_pendulum)
#   FLEXMBD_OUT   output folder (default: ./flexmbd_output, relative to the current directory)
#   FLEXMBD_WS    catkin workspace (default: $HOME/flexmbd_ws)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
scripts="${FLEXMBD_REPO_ROOT}/scripts"

case_name="${FLEXMBD_CASE:-double_pendulum}"
case_dir="${FLEXMBD_REPO_ROOT}/config/${case_name}"
urdf="${case_dir}/${case_name}.urdf"
config="${case_dir}/${case_name}.yaml"
for input in "${urdf}" "${config}"; do
  if [[ ! -f "${input}" ]]; then
    available="$(cd "${FLEXMBD_REPO_ROOT}/config" 2>/dev/null && ls -d -- */ 2>/dev/null | tr -d / | paste -sd ' ' || true)"
    die "case '${case_name}': missing ${input} (cases under config/: ${available:-none})"
  fi
done

mkdir -p "${FLEXMBD_OUT:-flexmbd_output}" || die "cannot create output folder ${FLEXMBD_OUT:-flexmbd_output}"
out_dir="$(cd "${FLEXMBD_OUT:-flexmbd_output}" && pwd -P)"

bash "${scripts}/install_deps.sh"
bash "${scripts}/build.sh"

csv="${out_dir}/${case_name}.csv"
runner="${FLEXMBD_WS}/devel/lib/flexmbd/flexmbd_run"
[[ -x "${runner}" ]] || die "runner ${runner} was not built"

# The one place that launches the main case. Once the ROS node exists this becomes
# roslaunch + bag recording, and the plot step below reads the bag.
main_command=("${runner}" --urdf "${urdf}" --config "${config}" --csv "${csv}")

echo "run_main: ${main_command[*]}"
rm -f "${csv}" "${out_dir}/${case_name}"_*.png
run_status=0
"${main_command[@]}" </dev/null || run_status=$?
plot=(/usr/bin/python3 "${scripts}/plot_csv.py" "${csv}" --out-dir "${out_dir}")

if ((run_status != 0)); then
  # A failed run still flushes what it computed: plot that, then report the failure.
  if [[ -s "${csv}" ]] && "${plot[@]}" 2>/dev/null; then
    die "case '${case_name}' failed (runner exit status ${run_status}); partial output plotted in ${out_dir}"
  fi
  die "case '${case_name}' failed (runner exit status ${run_status}); no plottable output"
fi
[[ -s "${csv}" ]] || die "case '${case_name}' wrote no CSV at ${csv}"
echo "run_main: plotting ${csv}"
"${plot[@]}" || die "plotting ${csv} failed"
echo "run_main: outputs in ${out_dir}"
