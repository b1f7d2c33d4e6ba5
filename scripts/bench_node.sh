#!/usr/bin/env bash
# Benchmarks the node against the runner and prints the figures (bench/node/README.md records them):
#   1. overhead: wall time of the node's run (real_time_factor 0, from its first sample to its last written)
#      over the runner's run of the same case (as the runner reports it: also from its first sample to its
#      last, without its start-up and loading), best of 5 (the machine may be shared): the node publishing
#      with no subscriber and with one on loopback (the four sample topics, and the stop and friction
#      topics where the case has them), the node recording its bag against the runner writing the same bag,
#      and the node publishing against the runner writing its CSV; on the double pendulum at 100 samples/s
#      (config/double_pendulum/, 200 s: 20001 samples), the antenna with friction (config/antenna/, 200 s:
#      4001 samples) and a 40-link chain (1 s: 101 samples, about 40 times the solver work per sample);
#      target node/runner < 1.2;
#   2. throughput: the sample rate the node sustains to one subscriber on loopback: double-pendulum runs
#      paced at real_time_factor 1 with rising output rates; sustained = no sample lost and the run keeps
#      wall-clock pace (within 5 %).
# Starts its own roscore on FLEXMBD_BENCH_PORT (default 11611) and stops it at the end. Builds first.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
scripts="${FLEXMBD_REPO_ROOT}/scripts"

bash "${scripts}/build.sh" all sample_rate_subscriber >/dev/null
set +u
source "${FLEXMBD_WS}/devel/setup.bash" || die "cannot source ${FLEXMBD_WS}/devel/setup.bash"
set -u
bin="${FLEXMBD_WS}/devel/lib/flexmbd"
urdf="${FLEXMBD_REPO_ROOT}/config/double_pendulum/double_pendulum.urdf"
case_yaml="${FLEXMBD_REPO_ROOT}/config/double_pendulum/double_pendulum.yaml"
work="$(mktemp -d /tmp/flexmbd_bench_XXXXXX)"

export ROS_MASTER_URI="http://localhost:${FLEXMBD_BENCH_PORT:-11611}"
roscore -p "${FLEXMBD_BENCH_PORT:-11611}" >"${work}/roscore.log" 2>&1 &
roscore_pid=$!
cleanup() {
  kill -INT "${roscore_pid}" 2>/dev/null || true
  wait "${roscore_pid}" 2>/dev/null || true
  rm -rf "${work}"
}
trap cleanup EXIT
timeout 30 bash -c 'until rosparam list >/dev/null 2>&1; do sleep 0.2; done' || die "roscore did not start"
rosparam set -t "${urdf}" /robot_description

# A case YAML with solver.t_end and output.rate_hz replaced, for the node (rosparam) and the runner alike.
write_case() {  # write_case OUT_FILE SOURCE_YAML T_END RATE_HZ
  /usr/bin/python3 - "$@" <<'PY'
import sys, yaml
path, source, t_end, rate = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
case = yaml.safe_load(open(source))
case.setdefault("solver", {})["t_end"] = t_end
case.setdefault("output", {})["rate_hz"] = rate
yaml.safe_dump(case, open(path, "w"))
PY
}

# A hanging chain of N links (1 kg, 0.25 m, hinges about y), released from 30 deg: a case whose solver
# cost per sample is N times the pendulum's, to separate the node's per-sample cost from the solver's.
write_chain() {  # write_chain URDF_FILE YAML_FILE N
  /usr/bin/python3 - "$@" <<'PY'
import sys
urdf, params, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
inertial = ('<inertial><origin xyz="0.125 0 0"/><mass value="1"/>'
            '<inertia ixx="1e-4" ixy="0" ixz="0" iyy="5.2e-3" iyz="0" izz="5.2e-3"/></inertial>')
links = "".join('<link name="link%d">%s</link>' % (k, inertial) for k in range(1, n + 1))
joints = "".join('<joint name="joint%d" type="continuous"><parent link="%s"/><child link="link%d"/>'
                 '<origin xyz="%g 0 %g"/><axis xyz="0 1 0"/></joint>'
                 % (k, "world" if k == 1 else "link%d" % (k - 1), k, 0 if k == 1 else 0.25, 10 if k == 1 else 0)
                 for k in range(1, n + 1))
open(urdf, "w").write('<robot name="chain"><link name="world"/>%s%s</robot>' % (links, joints))
open(params, "w").write("joints: {joint1: {initial: {position_deg: 30.0}}}\n"
                        "solver: {t_end: 1.0, dt: 1.0e-3, dt_max: 1.0e-2}\noutput: {rate_hz: 100}\n")
PY
}

# One run of the runner: prints "<run wall seconds, as the runner reports them> <process CPU seconds (user +
# system)>". Extra arguments go to the runner (e.g. --csv FILE).
runner_run() {  # runner_run URDF CASE_YAML [ARGUMENTS...]
  local cpu run_seconds
  cpu="$( { TIMEFORMAT='%U %S'; time "${bin}/flexmbd_run" --urdf "$1" --config "$2" "${@:3}" >"${work}/runner.txt"; } \
    2>&1 | awk '{print $1 + $2}')"
  run_seconds="$(sed -n 's/.*samples written in \([0-9.e+-]*\) s wall time.*/\1/p' "${work}/runner.txt")"
  [[ -n "${run_seconds}" ]] || die "the runner did not finish its run: $(cat "${work}/runner.txt")"
  echo "${run_seconds} ${cpu}"
}

# Runs the node on a case, with the benchmark subscriber if SUBSCRIBERS is 1; prints "<run wall seconds>
# <process CPU seconds> <subscriber's line>". The node's CPU time includes its start-up and all its threads.
# Extra arguments go to the node (e.g. _bag:=FILE).
node_run() {  # node_run URDF CASE_YAML REAL_TIME_FACTOR SUBSCRIBERS [ARGUMENTS...]
  rosparam set -t "$1" /robot_description
  rosparam delete /flexmbd >/dev/null 2>&1 || true
  rosparam load "$2" /flexmbd
  local subscriber_pid=""
  echo "no subscriber" >"${work}/subscriber.txt"
  if (($4 > 0)); then
    "${bin}/sample_rate_subscriber" flexmbd 2 >"${work}/subscriber.txt" &
    subscriber_pid=$!
  fi
  local cpu
  cpu="$( { TIMEFORMAT='%U %S'; time "${bin}/flexmbd_node" "_real_time_factor:=$3" "_wait_for_subscribers:=$4" "${@:5}" \
    >"${work}/node.txt" 2>&1; } 2>&1 | awk '{print $1 + $2}')"
  [[ -z "${subscriber_pid}" ]] || wait "${subscriber_pid}"
  local run_seconds
  run_seconds="$(sed -n 's/.*samples sent in \([0-9.e+-]*\) s wall time.*/\1/p' "${work}/node.txt")"
  [[ -n "${run_seconds}" ]] || die "the node did not finish its run: $(cat "${work}/node.txt")"
  echo "${run_seconds} ${cpu} $(cat "${work}/subscriber.txt")"
}

ratio() { echo "$1 $2" | awk '{printf "%.2f", $1 / $2}'; }

# Keeps the best (smallest wall time) of repeated runs: best_of NAME WALL REST... sets NAME_wall and NAME_rest.
best_of() {
  local name="$1" wall="$2" previous="${1}_wall"
  if [[ -z "${!previous:-}" ]] || awk "BEGIN {exit !(${wall} < ${!previous})}"; then
    printf -v "${name}_wall" '%s' "${wall}"
    printf -v "${name}_rest" '%s' "${*:3}"
  fi
}

# Best of 5 of the node and of the runner, their runs interleaved so that a shared machine's load changes
# weigh on both alike. RECORDING: "none" (the node publishes; the runner writes no output, then its CSV)
# or "bag" (both write the bag).
overhead() {  # overhead LABEL URDF CASE_YAML SUBSCRIBERS RECORDING
  local runner_wall="" runner_rest="" csv_wall="" csv_rest="" node_wall="" node_rest="" wall rest
  local node_args=() runner_args=()
  if [[ "$5" == bag ]]; then
    node_args=("_bag:=${work}/node.bag")
    runner_args=(--bag "${work}/runner.bag")
  fi
  for _ in 1 2 3 4 5; do
    read -r wall rest < <(runner_run "$2" "$3" "${runner_args[@]}")
    best_of runner "${wall}" "${rest}"
    if [[ "$5" == none ]]; then
      read -r wall rest < <(runner_run "$2" "$3" --csv "${work}/runner.csv")
      best_of csv "${wall}" "${rest}"
    fi
    read -r wall rest < <(node_run "$2" "$3" 0.0 "$4" "${node_args[@]}")
    best_of node "${wall}" "${rest}"
  done
  local node_cpu subscriber_line
  read -r node_cpu subscriber_line <<<"${node_rest}"
  echo "  $1:"
  if [[ "$5" == none ]]; then
    echo "    run wall time: node ${node_wall} s; runner without output ${runner_wall} s (ratio" \
         "$(ratio "${node_wall}" "${runner_wall}")), with its CSV ${csv_wall} s (ratio $(ratio "${node_wall}" "${csv_wall}"))"
    echo "    CPU (user + system, whole process, all threads): node ${node_cpu} s, runner ${runner_rest} s," \
         "with CSV ${csv_rest} s"
  else
    echo "    run wall time: node ${node_wall} s; runner ${runner_wall} s (ratio $(ratio "${node_wall}" "${runner_wall}"))"
    echo "    CPU (user + system, whole process, all threads): node ${node_cpu} s, runner ${runner_rest} s"
  fi
  echo "    subscriber: ${subscriber_line}"
}

echo "flexmbd node benchmark: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg), $(date -u +%Y-%m-%d)"

echo "overhead, node / runner, run wall time (best of 5; target < 1.2):"
write_case "${work}/pendulum_200s.yaml" "${case_yaml}" 200.0 100.0
overhead "double pendulum, 20001 samples, no subscriber" "${urdf}" "${work}/pendulum_200s.yaml" 0 none
overhead "double pendulum, 20001 samples, one subscriber" "${urdf}" "${work}/pendulum_200s.yaml" 1 none
overhead "double pendulum, 20001 samples, bag, no subscriber" "${urdf}" "${work}/pendulum_200s.yaml" 0 bag
antenna_urdf="${FLEXMBD_REPO_ROOT}/config/antenna/antenna.urdf"
antenna_yaml="${FLEXMBD_REPO_ROOT}/config/antenna/antenna_friction.yaml"
overhead "antenna with friction, 4001 samples, one subscriber" "${antenna_urdf}" "${antenna_yaml}" 1 none
overhead "antenna with friction, 4001 samples, bag, no subscriber" "${antenna_urdf}" "${antenna_yaml}" 0 bag
write_chain "${work}/chain40.urdf" "${work}/chain40.yaml" 40
overhead "40-link chain, 101 samples, one subscriber" "${work}/chain40.urdf" "${work}/chain40.yaml" 1 none

t_end=3.0
echo "throughput: double pendulum, ${t_end} s at real_time_factor 1, one subscriber on loopback:"
for rate in 1000 10000 20000 30000 40000 60000 80000 120000; do
  write_case "${work}/rate.yaml" "${case_yaml}" "${t_end}" "${rate}"
  read -r node_seconds _ subscriber_line < <(node_run "${urdf}" "${work}/rate.yaml" 1.0 1)
  expected="$(echo "${t_end} ${rate}" | awk '{printf "%d", $1 * $2 + 1}')"
  verdict="$(echo "${node_seconds} ${t_end} ${expected} ${subscriber_line}" |
    awk '{print ($5 == $3 && $9 == 0 && $1 <= 1.05 * $2) ? "sustained" : "NOT sustained"}')"
  echo "  ${rate} samples/s (${expected} samples): run took ${node_seconds} s for ${t_end} s;" \
       "${subscriber_line} -> ${verdict}"
done
