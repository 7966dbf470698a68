#!/usr/bin/env bash
# Every script of benchmarks/ and scripts/ as a newcomer calls it, from a
# folder that is not the repository's root, with relative paths: each
# benchmark's quick mode (or a small run where it has none), each plot
# script once on a small run; each must exit 0 and write the files its
# usage says. The peer benchmarks, whose peer programs are not Debian
# packages here, must say what is missing and exit 77 (skipped).
# set-up, run_default.sh and run_tests.sh build the program and are not run.
#
#   bash tests/scripts_quick.sh BINARY SOURCE_DIR
# It works in a fresh folder scripts_quick.run below the current one.
set -uo pipefail
binary=$(realpath "${1:?usage: scripts_quick.sh BINARY SOURCE_DIR}")
src=$(realpath "${2:?usage: scripts_quick.sh BINARY SOURCE_DIR}")
rm -rf scripts_quick.run
mkdir scripts_quick.run && cd scripts_quick.run || exit 1
# Relative paths, as a user in this folder would type them.
binary=$(realpath --relative-to=. "$binary")
src=$(realpath --relative-to=. "$src")
build=$(dirname "$binary")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
failures=0

# run NAME EXPECTED_EXIT COMMAND...: run the command, log to NAME.log, and
# say how it ended and how long it took.
run() {
  local name=$1 expected=$2; shift 2
  local start end code
  start=$(date +%s.%N)
  "$@" > "$name.log" 2>&1
  code=$?
  end=$(date +%s.%N)
  if [ "$code" -eq "$expected" ]; then
    printf '%-22s exit %3d  %6.1f s\n' "$name" "$code" \
      "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')"
  else
    printf '%-22s exit %3d (expected %d)  FAILED; the end of %s.log:\n' \
      "$name" "$code" "$expected" "$name"
    tail -15 "$name.log"
    failures=$((failures + 1))
  fi
}

# expect FILE...: each file exists and is not empty.
expect() {
  for f in "$@"; do
    if [ ! -s "$f" ]; then
      echo "  missing or empty: $f"
      failures=$((failures + 1))
    fi
  done
}

# expect_text FILE TEXT: FILE holds TEXT.
expect_text() {
  if ! grep -qF -- "$2" "$1" 2>/dev/null; then
    echo "  $1 does not say: $2"
    failures=$((failures + 1))
  fi
}

b=$src/benchmarks

run direct_solvers 0 python3 "$b/direct_solvers.py" --quick --binary "$binary" \
  --markdown direct.md
expect_text direct.md "<!-- DIRECT-SOLVERS BEGIN -->"
expect_text direct.md "| yes |"

run disk_chain 0 python3 "$b/disk_chain.py" --quick --binary "$binary" --out chain
expect chain/chain_2/summary.json chain/chain_3/summary.json
expect_text disk_chain.log "| 3 | 3 |"

run effects 0 python3 "$b/effects.py" --quick --binary "$binary" --out effects \
  --markdown effects.md
expect_text effects.md "<!-- EFFECTS BEGIN -->"
expect effects/overhead_r3_far_1/summary.json effects/rigid_G2_load1/summary.json

run error_estimates 0 python3 "$b/error_estimates.py" --quick --binary "$binary" \
  --work estimates --markdown estimates.md
expect_text estimates.md "<!-- error-estimates BEGIN -->"
expect estimates/hertz_adaptive/summary.json estimates/hertz_block/summary.json \
  estimates/hertz_sphere/summary.json

run fault_drill 0 python3 "$b/fault_drill.py" --build "$build" \
  --scene "$src/prm/ironing.prm" --interrupts 4 --output drill
expect drill/fault_drill.json drill/reference/run/reactions.csv
expect_text fault_drill.log "the same as the run without a stop: yes"

run friction_cost 0 python3 "$b/friction_cost.py" --quick --binary "$binary" --out friction
expect_text friction_cost.log "| sliding block mu = 0.3"

run hard_cases 0 python3 "$b/hard_cases.py" --quick --build "$build" --out hard
expect hard/ssnv187_corner_ipopt/summary.json hard/stiff_on_soft_block_newton-penalty/summary.json
expect_text hard_cases.log "6 converged, 0 not converged"

run peer_freefem 77 python3 "$b/peer_freefem.py" --binary "$binary" --peer no_peer
expect_text peer_freefem.log "peer_freefem.py: skipped:"
run peer_getfem3d 77 python3 "$b/peer_getfem3d.py" --binary "$binary" --peer no_peer
expect_text peer_getfem3d.log "peer_getfem3d.py: skipped:"

run scaling 0 python3 "$b/scaling.py" --quick --binary "$binary" --out scaling \
  --markdown scaling.md
expect scaling/results.json
expect_text scaling.md "<!-- SCALING-e BEGIN -->"

run solver_comparison 0 python3 "$b/solver_comparison.py" --build "$build" \
  --levels 3 --out comparison
expect comparison/ipopt_L3/summary.json comparison/interior-point_L3/summary.json \
  comparison/newton-penalty_L3/summary.json
expect_text solver_comparison.log "| 3 | interior-point |"

run two_body_large 0 python3 "$b/large_3d.py" --quick --binary "$binary" \
  --work large --markdown large.md
expect large/run0/summary.json
expect_text large.md "<!-- two-body-large BEGIN -->"
run many_bodies_large 0 python3 "$b/large_3d.py" --scene many-bodies --quick \
  --binary "$binary" --work many --markdown many.md
expect many/run0/summary.json
expect_text many.md "<!-- many-bodies-large BEGIN -->"

# Plot scripts, on small runs of the tutorial scene and of a study.
printf 'include %s\nset Output directory = punch\nsubsection Mesh\n  set Gmsh file = %s\nend\n' \
  "$src/prm/tutorial/punch.prm" "$src/prm/tutorial/punch.msh" > punch.prm
run punch 0 "$binary" punch.prm
run plot_profile 0 bash "$src/scripts/plot_profile.sh" punch "tutorial punch"
expect punch/contact_profile.png
run plot_contact_history 0 bash "$src/scripts/plot_contact_history.sh" punch history
expect history/contact_history.png
run plot_ironing 0 bash "$src/scripts/plot_ironing.sh" ironing drill/reference/run drill/drill/run
expect ironing/ironing_reactions.png ironing/ironing_steps.png

# The ring crush's reaction against stroke, on a coarse ring (64 cells).
printf 'include %s\nset Output directory = ring_crush_half\nsubsection Mesh\n  set Global refinements = 1\nend\nsubsection Output\n  set Format = none\nend\n' \
  "$src/prm/ring_crush.prm" > ring.prm
run ring 0 "$binary" ring.prm
run plot_ring_crush 0 python3 "$src/scripts/plot_ring_crush.py" ring.png ring_crush_half
expect ring.png

cat > study.prm <<EOF
include $src/prm/hertz_adaptive.prm
set Output directory = study
subsection Study
  set Quantities = hertz_a, hertz_p0
  set Reference variant = uniform
  subsection Variant 1
    set Name = uniform
    set Settings = Mesh refinement/Number of cycles = 0
    set Series entry = Mesh/Global refinements
    set Series values = 2, 3, 4
  end
end
EOF
run study 0 "$binary" --study study.prm
rm -f study/study/*.png study/study/study_tables.md
run plot_study 0 python3 "$src/scripts/plot_study.py" study/study
expect study/study/error_vs_time.png study/study/error_vs_dofs.png study/study/study_tables.md

if [ "$failures" -eq 0 ]; then
  echo "scripts_quick: every script ran and wrote its files"
else
  echo "scripts_quick: $failures failure(s)"
  exit 1
fi
