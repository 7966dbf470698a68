#!/usr/bin/env bash
# Quick start 2: set up, build, and run the test suite (ctest). Tests whose
# name ends in "_long" are skipped unless SIGNORINI_LONG_TESTS=1.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
cd build
exclude=()
[ "${SIGNORINI_LONG_TESTS:-0}" = "1" ] || exclude=(-E '_long')
ctest --output-on-failure -j "$(nproc)" "${exclude[@]}" "$@"
