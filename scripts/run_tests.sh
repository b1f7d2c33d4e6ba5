#!/usr/bin/env bash
# Installs what is missing, builds flexmbd, builds and runs every test (gtest and rostest) and
# prints the per-suite results. The last line is `N passed, M failed`.
# Exits non-zero when the build failed, a test failed or errored, or no test ran.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
scripts="${FLEXMBD_REPO_ROOT}/scripts"

bash "${scripts}/install_deps.sh"

# The tests' files go to a directory of this run's own (gtest's testing::TempDir() reads TEST_TMPDIR): two test
# runs on one machine would otherwise write the same /tmp/<name>.csv and one read what the other wrote.
TEST_TMPDIR="$(mktemp -d /tmp/flexmbd_tests_XXXXXX)"
export TEST_TMPDIR
trap 'rm -rf "${TEST_TMPDIR}"' EXIT

failed_steps=()
bash "${scripts}/build.sh" || failed_steps+=("build")

results="${FLEXMBD_WS}/build/test_results"
rm -rf "${results}"
targets=""
if [[ -f "${FLEXMBD_WS}/build/build.ninja" ]]; then
  targets="$(ninja -C "${FLEXMBD_WS}/build" -t targets all 2>/dev/null | sed -n 's/^\([^:]*\): .*/\1/p' || true)"
fi
if [[ -z "${targets}" ]]; then
  failed_steps+=("configuring the workspace")
elif ! grep -qx 'run_tests_flexmbd' <<<"${targets}"; then
  failed_steps+=("finding tests: CMake defined no test target (run_tests_flexmbd)")
else
  # run_tests_flexmbd runs each test once its own executable is built (catkin's plain run_tests
  # first builds every test executable), and -k 0 goes on past a test that does not compile, so one
  # broken test file does not hide the results of the others. Old results were removed above. -j4: two tests
  # besides the two compiles CMakeLists.txt allows (its job pool): most rostests wait on the clock or the master.
  bash "${scripts}/build.sh" run_tests_flexmbd -k 0 -j4 || failed_steps+=("building or running the tests")
fi

echo
echo "Test results (${results}):"
if ((${#failed_steps[@]} > 0)); then
  printf 'error: run_tests.sh: failed step: %s\n' "${failed_steps[@]}" >&2
fi
# catkin names each test's target run_tests_flexmbd_<type>_<name> and its result <type>-<name>.xml
# (a rostest's <name> keeps its .test extension in the target, not in the result);
# a test whose result is missing (its executable did not build) is counted as failed.
expected_suites=()
while read -r target; do
  suite="${target#run_tests_flexmbd_}"
  if [[ "${suite}" == *_* ]]; then
    expected_suites+=("${suite/_/-}")
  fi
done < <(grep '^run_tests_flexmbd_' <<<"${targets}")
summary_status=0
/usr/bin/python3 "${scripts}/summarize_test_results.py" "${results}" "${expected_suites[@]}" || summary_status=$?

if ((${#failed_steps[@]} > 0 || summary_status != 0)); then
  exit 1
fi
