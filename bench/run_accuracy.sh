#!/bin/bash
# Run time vs error benchmark (bench/accuracy_bench.cpp) on the ellipsoid and n = 6 beds, then a
# Pareto plot (cost per particle and simulated ms against the 99th-percentile contact force
# error). Run from the repository root after building; writes to OUT (default bench-out/).
# About 25 minutes, most of it the true-gap law's variants on the n = 6 bed. SETTLE (seconds)
# settles the beds that long instead of their scenes' 0.15 s (0.4: at rest).
#   bash bench/run_accuracy.sh [steps, default 1000]
#   SETTLE=0.4 OUT=bench-rest bash bench/run_accuracy.sh
set -eu
OUT=${OUT:-bench-out}
STEPS=${1:-1000}
SETTLE=${SETTLE:-}
mkdir -p "$OUT"
for bed in ellipsoid sq6; do
  ./build/bench/bench_accuracy "bench/scenes/bed_$bed.yaml" "$STEPS" "$OUT/accuracy_$bed.tsv" ${SETTLE:+"$SETTLE"} | tee "$OUT/accuracy_$bed.txt"
done
# Force errors of exactly 0 (the reference itself) sit at 1e-16 on the log axis.
gnuplot <<GP
set terminal pngcairo size 1100,500 noenhanced
set output "$OUT/accuracy_pareto.png"
set datafile separator "\t"
set multiplot layout 1,2
do for [bed in "ellipsoid sq6"] {
  set title "run time vs force error: ".bed." bed (1 thread)"
  set logscale x
  set xlabel "contact force error |F - F_ref| / |F_ref|, 99th percentile"
  set ylabel "run time per particle and simulated ms (us)"
  set key off
  plot "$OUT/accuracy_".bed.".tsv" skip 1 using ((\$5 > 1e-16 ? \$5 : 1e-16)):3 with points pt 7 ps 1.2, \
       "" skip 1 using ((\$5 > 1e-16 ? \$5 : 1e-16)):3:1 with labels offset 0.5,0.5 left font ",7"
}
unset multiplot
GP
echo "table: $OUT/accuracy_*.tsv, plot: $OUT/accuracy_pareto.png"
