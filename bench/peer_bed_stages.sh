#!/bin/bash
# Seconds by stage of resumed runs of a settled peer bed (../shared/peers/run_side_by_side.sh's
# scene B), for comparing binaries or code paths on this machine, interleaved:
#   bench/peer_bed_stages.sh VARIANT THREADS REPS STEPS LABEL=BINARY[:SIMD] ...
# VARIANT: sphere, ellipsoid, sq6 (or a _vs variant); the settle checkpoint is read from
# $RUN/sqdem/full_<VARIANT>/ (RUN as for run_side_by_side.sh, default /tmp/peer-runs: run its
# `settle` phase first); STEPS: resumed steps (the bed stage shortened to them, no frames).
# Prints per label the run with the least wall time: wall, contacts, reduction, integration (s).
set -eu
[ $# -ge 5 ] || { sed -n 2,8p "$0"; exit 2; }
variant=$1 threads=$2 reps=$3 steps=$4; shift 4
case $variant in sphere|ellipsoid|sq6|ellipsoid_vs|sq6_vs) ;; *) echo "unknown variant '$variant'"; exit 2;; esac
[[ $threads =~ ^[0-9]+$ && $reps =~ ^[0-9]+$ && $steps =~ ^[0-9]+$ ]] || { echo "THREADS, REPS and STEPS are integers"; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
peers=${PEERS:-$here/../../shared/peers}
run=${RUN:-/tmp/peer-runs}
checkpoint=$run/sqdem/full_$variant/bench_${variant}_after_settle.checkpoint
[ -f "$checkpoint" ] || { echo "no settle checkpoint $checkpoint: run the side-by-side script's settle phase"; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The bed stage shortened to STEPS (dt = 1e-5 s), no frames.
sed -e "s/^\(    duration: \)0.1 .*/\1$(python3 -c "print($steps * 1e-5)")/" -e 's/frames: 1/frames: 0/' \
  "$peers/bench_$variant.yaml" > "$work/bench_$variant.yaml"
seconds() { python3 -c "print(f'{$1 * $2 / 100:.3f}')"; }
for r in $(seq 1 "$reps"); do
  for spec in "$@"; do
    label=${spec%%=*} binary=${spec#*=} simd=""
    [[ $binary == *:* ]] && simd=${binary##*:} binary=${binary%:*}
    log=$work/$label.log
    "$binary" run "$work/bench_$variant.yaml" --threads "$threads" ${simd:+--simd "$simd"} --out "$work/$label" \
      --resume "$checkpoint" > "$log" 2>&1 || { echo "$label failed: $(tail -3 "$log")"; exit 1; }
    rm -rf "${work:?}/$label"
    wall=$(sed -n 's/^summary: [0-9]* steps in \([0-9.]*\) s.*/\1/p' "$log")
    share() { sed -n "s/.*$1 \([0-9.]*\) %.*/\1/p" "$log"; }
    echo "$label $wall $(seconds "$wall" "$(share 'contacts (detection and laws)')") $(seconds "$wall" "$(share reduction)") $(seconds "$wall" "$(share integration)")"
  done
done | sort -k1,1 -k2,2n | awk 'BEGIN { print "label wall_s contacts_s reduction_s integration_s" } $1 != last { print; last = $1 }'
