#!/usr/bin/env bash
# Quick start 1: set up, build, and run the default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build && ./signorini ../prm/default.prm
