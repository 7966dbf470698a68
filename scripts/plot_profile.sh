#!/bin/bash
# Draw the contact pressure profile of a run against its reference (Hertz)
# pressure: reads OUTPUT_DIR/contact_profile.csv, writes
# OUTPUT_DIR/contact_profile.png next to it. Needs gnuplot (Debian
# gnuplot-nox, installed by scripts/setup.sh).
#
#   bash scripts/plot_profile.sh output/default [title]
set -euo pipefail
dir=${1:?usage: plot_profile.sh OUTPUT_DIR [title]}
title=${2:-$(basename "$dir")}
csv="$dir/contact_profile.csv"
[ -r "$csv" ] || { echo "plot_profile.sh: cannot read $csv" >&2; exit 2; }
header=$(head -1 "$csv")
# Column numbers by name (the CSV has X, Y[, Z], x, y[, z], ...).
col() { echo "$header" | tr ',' '\n' | grep -nx "$1" | cut -d: -f1; }
cx=$(col x); cp=$(col pressure); cr=$(col reference_pressure || true)
# Plot up to 1.5 times the widest loaded node.
xmax=$(awk -F, -v cx="$cx" -v cp="$cp" 'NR > 1 && $cp > 0 && $cx > m { m = $cx } END { print (m > 0 ? 1.5 * m : 1) }' "$csv")
reference=""
if [ -n "$cr" ]; then
  reference=", '$csv' every ::1 using $cx:$cr with lines lw 2 lc rgb '#d62728' title 'reference (Hertz)'"
fi
gnuplot <<GP
set terminal pngcairo size 900,600 enhanced font ',12'
set output '$dir/contact_profile.png'
set datafile separator ','
set title "$title: contact pressure along the contact boundary"
set xlabel 'x (current position)'
set ylabel 'contact pressure'
set xrange [0:$xmax]
set yrange [0:*]
set grid
set key top right
plot '$csv' every ::1 using $cx:$cp with linespoints pt 7 ps 0.8 lc rgb '#1f77b4' title 'computed (nodal)'$reference
GP
echo "wrote $dir/contact_profile.png"
