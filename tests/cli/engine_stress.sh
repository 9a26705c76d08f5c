# Engine stress suite (label `stress`): each scene of tests/scenes/stress/ runs to its end with
# 0 unresolved contacts, 0 deep overlaps, no non-finite number in its log, and a kinetic energy
# that has decayed to below a quarter of its peak (the beds come to rest).
. "$(dirname "$0")/lib.sh"
for scene in "$source_dir"/tests/scenes/stress/*.yaml; do
  name=$(basename "$scene" .yaml)
  out="$scratch/$name"
  if ! "$sqdem" run "$scene" --out "$out" > "$scratch/$name.log" 2>&1; then
    fail "$name: exit code $?: $(tail -3 "$scratch/$name.log")"
    continue
  fi
  grep -E "^detector:" "$scratch/$name.log" | sed "s/^/$name: /"
  check "$name: 0 unresolved, 0 deep overlaps" grep -q "0 unresolved, 0 deep overlaps" "$scratch/$name.log"
  check "$name: finite log" sh -c "! grep -qiE 'nan|inf' '$out/$name.csv'"
  check "$name: kinetic energy decayed" awk -F, 'NR > 1 { if ($4 > peak) peak = $4; last = $4 }
    END { printf "  kinetic energy: peak %g J, last %g J\n", peak, last; exit !(peak > 0 && last < 0.25 * peak) }' "$out/$name.csv"
done
finish
