#!/bin/bash
# Contact history of a run: the resultant contact force (each component)
# and the contact area (length in 2D) against the load time t, one point
# per converged load step, from RUN_DIR/load_steps.csv (columns
# contact_force_x/y[/z] and contact_area). Writes contact_history.png into
# OUT (default: RUN_DIR). Needs gnuplot (installed by scripts/setup.sh).
#
#   bash scripts/plot_contact_history.sh output/hertz_rigid [OUT_DIR]
set -euo pipefail
dir=${1:?usage: plot_contact_history.sh RUN_DIR [OUT_DIR]}
out=${2:-$dir}
csv="$dir/load_steps.csv"
[ -r "$csv" ] || { echo "plot_contact_history.sh: cannot read $csv" >&2; exit 2; }
mkdir -p "$out"
header=$(head -1 "$csv")
col() { echo "$header" | tr ',' '\n' | { grep -nx "$1" || true; } | cut -d: -f1; }
area=$(col contact_area)
[ -n "$area" ] || { echo "plot_contact_history.sh: $csv has no contact_area column" >&2; exit 2; }
forces=""
for c in x y z; do
  k=$(col "contact_force_$c")
  [ -n "$k" ] && forces+="'$csv' every ::1 using $(col time):$k with linespoints pt 7 ps 0.6 lw 2 title 'F_$c', "
done
gnuplot <<GP
set terminal pngcairo size 900,700
set output '$out/contact_history.png'
set datafile separator ','
set multiplot layout 2,1 title 'contact history: $(basename "$dir")'
set xlabel 't'
set ylabel 'resultant contact force on body 1'
set key left top
set grid
plot ${forces%, }
set ylabel 'contact area (length in 2D)'
plot '$csv' every ::1 using $(col time):$area with linespoints pt 7 ps 0.6 lw 2 title 'area'
unset multiplot
GP
echo "$out/contact_history.png"
