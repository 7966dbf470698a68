#!/usr/bin/env bash
# The test suite under every OpenBLAS kernel this CPU can execute, and with
# one thread per rank: the tests must pass on any x86-64 machine, whose
# BLAS picks its own kernel (issue 52: Ipopt's iteration counts changed
# with the kernel and a pinned count failed on another CPU).
#
#   bash scripts/check_kernels.sh [--all] [--kernels "Nehalem Zen"] [CTEST ARGS...]
#
# By default it runs the path-sensitive tests (ctest label path_sensitive:
# those whose expected output holds iteration, stage or step counts, or
# values of a solver's path; tests/CMakeLists.txt) under each kernel; with
# --all, the whole suite (tests named *_long excepted, as run_tests.sh
# does). Then the same tests with DEAL_II_NUM_THREADS=1. Needs a build in
# ./build (scripts/setup.sh). Prints one line per run and a closing
# "N passed, M failed" line counting the runs; exits 1 if any run failed.
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

select=(-L path_sensitive)
kernels=""
ctest_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --all) select=(); shift ;;
    --kernels) kernels="$2"; shift 2 ;;
    *) ctest_args+=("$1"); shift ;;
  esac
done
[ -d build ] || { echo "check_kernels.sh: no ./build: run scripts/setup.sh first" >&2; exit 2; }

# OpenBLAS's x86-64 kernels, oldest first, with the CPU flags each needs.
flags=" $(grep -m1 '^flags' /proc/cpuinfo | cut -d: -f2) "
has() { for f in "$@"; do [[ "$flags" == *" $f "* ]] || return 1; done; }
if [ -z "$kernels" ]; then
  kernels="default Nehalem"
  has avx && kernels+=" Sandybridge"
  has avx2 fma && kernels+=" Haswell Zen"
  has avx512f avx512bw avx512dq avx512vl && kernels+=" SkylakeX"
  has avx512f avx512bw avx512dq avx512vl avx512_bf16 && kernels+=" Cooperlake"
fi

# A deal.II-style test runs only when its output is older than its
# executable or input: the outputs of the last run go, so that each
# kernel's run runs every selected test again.
forget_outputs() { find build/tests -path '*.release/*' -name output -type f -delete 2>/dev/null || true; }

passed=0 failed=0
run() { # label, then the environment to run ctest in
  local label=$1; shift
  local log="build/check_kernels-${label}.log"
  local start=$SECONDS
  forget_outputs
  if (cd build && env "$@" ctest -j "$(nproc)" -E _long "${select[@]}" \
        "${ctest_args[@]}" > "../$log" 2>&1); then
    passed=$((passed + 1)); verdict=passed
  else
    failed=$((failed + 1)); verdict="FAILED ($(grep -c '\*\*\*' "$log" || true) failing; $log)"
  fi
  printf '%-28s %s in %d s: %s\n' "$label" \
    "$(grep -Eo '[0-9]+% tests passed, [0-9]+ tests failed out of [0-9]+' "$log" || echo '?')" \
    $((SECONDS - start)) "$verdict"
}
for k in $kernels; do
  if [ "$k" = default ]; then
    # The kernel OpenBLAS picks itself on this CPU.
    run "kernel=default" -u OPENBLAS_CORETYPE -u OPENBLAS_L2_SIZE
  else
    run "kernel=$k" OPENBLAS_CORETYPE="$k"
  fi
done
run "DEAL_II_NUM_THREADS=1" DEAL_II_NUM_THREADS=1
forget_outputs # the next ctest runs every test under the machine's kernel
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
