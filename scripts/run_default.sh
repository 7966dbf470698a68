#!/usr/bin/env bash
# Quick start 1: set up, build, run the default scene (Hertz contact on a
# rigid plane) and plot its contact pressure against Hertz.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build
./signorini ../prm/default.prm
bash ../scripts/plot_profile.sh output/default "Hertz, rigid plane"
