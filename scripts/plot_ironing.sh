#!/bin/bash
# Ironing report: reaction forces on the die's top edge against t, Newton
# iterations and largest penetration per load step, for one or more runs
# of prm/ironing.prm (e.g. the nodal and the integral form), and the
# smoothness measure of the slide: the largest step-to-step jump of the
# horizontal reaction relative to the vertical one, over t > 1 (the
# vertical is Ry in 2D, Rz in 3D).
# Reads DIR/reactions.csv and DIR/load_steps.csv of each run; writes
# ironing_reactions.png and ironing_steps.png into OUT (default: the first
# DIR). Needs gnuplot (installed by scripts/setup.sh).
#
#   bash scripts/plot_ironing.sh OUT output/ironing output/ironing_integral
set -euo pipefail
out=${1:?usage: plot_ironing.sh OUT_DIR RUN_DIR [RUN_DIR ...]}
shift
[ $# -ge 1 ] || { echo "plot_ironing.sh: give at least one run directory" >&2; exit 2; }
mkdir -p "$out"
reactions="" steps="" penetration=""
colors=('#1f77b4' '#d62728' '#2ca02c' '#9467bd')
k=0
printf '%-28s %6s %8s %12s %12s %14s %14s\n' run steps newton Ry_t1 Rx_t1 max_jump_Rx/Ry mean_Rx/Ry
for dir in "$@"; do
  for f in reactions.csv load_steps.csv; do
    [ -r "$dir/$f" ] || { echo "plot_ironing.sh: cannot read $dir/$f" >&2; exit 2; }
  done
  name=$(basename "$dir")
  c=${colors[$((k % 4))]}
  # reactions.csv: time,Rx_<id>,Ry_<id>: the support's force on the die;
  # the die pushes the block with the opposite force.
  # The vertical reaction: Ry in 2D, Rz in 3D (a fourth column).
  v=3; [ "$(head -1 "$dir/reactions.csv" | tr ',' '\n' | wc -l)" -ge 4 ] && v=4
  reactions+="'$dir/reactions.csv' every ::1 using 1:(-\$$v) with lines lw 2 lc rgb '$c' title '$name: vertical', "
  reactions+="'$dir/reactions.csv' every ::1 using 1:(-\$2) with lines lw 2 dt 2 lc rgb '$c' title '$name: horizontal', "
  header=$(head -1 "$dir/load_steps.csv")
  col() { echo "$header" | tr ',' '\n' | { grep -nx "$1" || true; } | cut -d: -f1; }
  # Iterations of the stage solver: Newton's or Ipopt's (Method = ipopt).
  its=$(col newton_iterations); [ -n "$its" ] || its=$(col ipopt_iterations)
  steps+="'$dir/load_steps.csv' every ::1 using $(col time):$its with impulses lw 1 lc rgb '$c' title '$name', "
  penetration+="'$dir/load_steps.csv' every ::1 using $(col time):$(col max_penetration_over_h) with points pt 7 ps 0.5 lc rgb '$c' title '$name', "
  newton=$(awk -F, -v c="$its" 'NR > 1 { s += $c } END { print s }' "$dir/load_steps.csv")
  awk -F, -v name="$name" -v newton="$newton" -v v="$v" '
    NR == 1 { next }
    { n++ }
    $1 <= 1 + 1e-12 { ry1 = -$v; rx1 = -$2 }
    $1 > 1 + 1e-12 && have {
      jump = ($2 - px) / $v; if (jump < 0) jump = -jump; if (jump > worst) worst = jump
      ratio = $2 / $v; if (ratio < 0) ratio = -ratio; sum += ratio; m++ }
    { px = $2; have = 1 }
    END { printf "%-28s %6d %8d %12.4e %12.4e %14.4f %14.4f\n", name, n, newton, ry1, rx1, worst, (m ? sum / m : 0) }' \
    "$dir/reactions.csv"
  k=$((k + 1))
done
gnuplot <<GP
set terminal pngcairo size 1000,600 noenhanced font ',12'
set datafile separator ','
set grid
set output '$out/ironing_reactions.png'
set title 'Shallow ironing: force of the die on the block (reaction on its top edge, sign reversed)'
set xlabel 'pseudo-time t (0-1: indentation, 1-2: slide of 10)'
set ylabel 'force per unit thickness'
set key bottom left
plot ${reactions%, }
set output '$out/ironing_steps.png'
set multiplot layout 2,1
set title 'Newton iterations per load step (all penalty stages)'
set xlabel 't'
set ylabel 'iterations'
set key top left
plot ${steps%, }
set title 'largest penetration / local face size per load step'
set ylabel 'penetration / h'
set logscale y
plot ${penetration%, }
unset multiplot
GP
echo "wrote $out/ironing_reactions.png and $out/ironing_steps.png"
