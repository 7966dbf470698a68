#!/bin/bash
# Draw the contact pressure profile of a run against its reference (Hertz)
# pressure: reads OUTPUT_DIR/contact_profile.csv, writes
# OUTPUT_DIR/contact_profile.png next to it. Needs gnuplot (Debian
# gnuplot-nox, installed by scripts/setup.sh). In 2D the abscissa is x; in
# 3D (the CSV has a z column) it is the distance r from the vertical line
# through CENTER (x0,y0; default 0,0), every node of the surface a point.
#
#   bash scripts/plot_profile.sh output/default [title]
#   bash scripts/plot_profile.sh output/hertz_sphere [title] [x0,y0]
set -euo pipefail
dir=${1:?usage: plot_profile.sh OUTPUT_DIR [title] [x0,y0]}
title=${2:-$(basename "$dir")}
center=${3:-0,0}
x0=${center%,*}; y0=${center#*,}
csv="$dir/contact_profile.csv"
[ -r "$csv" ] || { echo "plot_profile.sh: cannot read $csv" >&2; exit 2; }
header=$(head -1 "$csv")
# Column numbers by name (the CSV has X, Y[, Z], x, y[, z], ...).
col() { echo "$header" | tr ',' '\n' | grep -nx "$1" | cut -d: -f1; }
cx=$(col x); cy=$(col y); cz=$(col z || true); cp=$(col pressure); cr=$(col reference_pressure || true)
if [ -n "$cz" ]; then
  # 3D: r from the vertical line through (x0, y0); the reference, a
  # function of r, is drawn through its values sorted by r.
  abscissa="(sqrt((\$$cx-($x0))**2+(\$$cy-($y0))**2))"
  xlabel="r = distance from ($x0, $y0) in the x-y plane (current position)"
  points="points pt 7 ps 0.6"
  smooth="smooth unique"
  # Up to 1.5 times the widest node with at least 1% of the peak pressure
  # (Ipopt leaves tiny multipliers on free nodes).
  xmax=$(awk -F, -v cx="$cx" -v cy="$cy" -v cp="$cp" -v x0="$x0" -v y0="$y0" 'NR == FNR { if (FNR > 1 && $cp > pmax) pmax = $cp; next } FNR > 1 && $cp > 0.01 * pmax { r = sqrt(($cx-x0)^2 + ($cy-y0)^2); if (r > m) m = r } END { print (m > 0 ? 1.5 * m : 1) }' "$csv" "$csv")
else
  abscissa="$cx"
  xlabel="x (current position)"
  points="linespoints pt 7 ps 0.8"
  smooth=""
  # Plot up to 1.5 times the widest loaded node.
  xmax=$(awk -F, -v cx="$cx" -v cp="$cp" 'NR > 1 && $cp > 0 && $cx > m { m = $cx } END { print (m > 0 ? 1.5 * m : 1) }' "$csv")
fi
reference=""
if [ -n "$cr" ]; then
  reference=", '$csv' every ::1 using $abscissa:$cr $smooth with lines lw 2 lc rgb '#d62728' title 'reference (Hertz)'"
fi
gnuplot <<GP
set terminal pngcairo size 900,600 enhanced font ',12'
set output '$dir/contact_profile.png'
set datafile separator ','
set title "$title: contact pressure along the contact boundary" noenhanced
set xlabel '$xlabel'
set ylabel 'contact pressure'
set xrange [0:$xmax]
set yrange [0:*]
set grid
set key top right
plot '$csv' every ::1 using $abscissa:$cp with $points lc rgb '#1f77b4' title 'computed (nodal)'$reference
GP
echo "wrote $dir/contact_profile.png"
