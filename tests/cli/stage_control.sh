# Stage control on tests/scenes/small_bed.yaml: a wall moves only in the stages that move it,
# and the kinetic-energy stop criterion works without gravity through stop.velocity_scale.
. "$(dirname "$0")/lib.sh"
base="$source_dir/tests/scenes/small_bed.yaml"

# The lid moves down in 'pour' (10 mm/s for 10 ms) and must stand still in 'press', which does
# not move it (the CSV's wall1_z_m).
sed 's/duration: 0.06/duration: 0.01\n    move_wall: {wall: 1, velocity: [0, 0, -0.01]}/; s/    move_wall: {wall: 1, velocity: \[0, 0, -0.1\]}//; s/duration: 0.02/duration: 0.005/' \
  "$base" > "$scratch/walls.yaml"
check "two-stage run" "$sqdem" run "$scratch/walls.yaml" --out "$scratch/walls" > /dev/null
check "the lid moved in 'pour' and stood still in 'press'" awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  $3 == "pour" { last = $c["wall1_z_m"] }
  $3 == "press" { z = $c["wall1_z_m"]; if (first == "") first = z; if (z != first) moved = 1 }
  END { printf "  lid z: end of pour %s, press %s%s\n", last, first, moved ? " (moved)" : "";
        exit !(last < 0.012 - 9e-5 && first == last && !moved) }' "$scratch/walls/walls.csv"

# Without gravity: kinetic_energy_ratio needs velocity_scale, and stops with it.
sed 's/^gravity: .*$//' "$base" | sed 's/duration: 0.06/duration: 0.06\n    stop: {kinetic_energy_ratio: 1.0e-3}/' > "$scratch/nograv.yaml"
expect_error "kinetic_energy_ratio without gravity or velocity_scale" 1 \
  "'stages\[0\].stop.kinetic_energy_ratio': without gravity needs velocity_scale" "$sqdem" run "$scratch/nograv.yaml" --out "$scratch/ng"
sed 's/stop: {kinetic_energy_ratio: 1.0e-3}/stop: {kinetic_energy_ratio: 1.0e-3, velocity_scale: 0.1}/' "$scratch/nograv.yaml" > "$scratch/vscale.yaml"
"$sqdem" run "$scratch/vscale.yaml" --out "$scratch/vs" > "$scratch/vs.log" 2>&1
check "velocity_scale stops the resting bed at once" grep -q "stage 'pour': t = .*kinetic energy ratio below" "$scratch/vs.log"
# Progress records (stdout is not a terminal here): a stage with a stop criterion shows the
# watched quantity against its target, not a percentage.
sed 's/    duration: 0.06/    duration: 0.2\n    stop: {kinetic_energy_ratio: 1.0e-3}/; s/duration: 0.02/duration: 0.002/' "$base" > "$scratch/ke.yaml"
"$sqdem" run "$scratch/ke.yaml" --out "$scratch/ke" --progress-every 0.2 > "$scratch/ke.log" 2>&1
check "progress records watch the stop quantity" grep -Eq "^progress: \[pour\] t = .* E_kin ratio [0-9.e+-]+, stops below 0.001; [0-9]+ steps/s" "$scratch/ke.log"
check "no percentage for a stage with a stop" sh -c "! grep -q '^progress: \[pour\] .*%' '$scratch/ke.log'"
expect_error "--progress-every -1" 2 "--progress-every = '-1': expected seconds in \[0, 1e6\]" "$sqdem" run "$base" --progress-every -1
# A porosity stop: the lid's press ends when the bed's porosity between floor and lid (1 -
# particle volume / (box cross-section x gap)) reaches 0.875 (0.89 where the lid starts); the CSV's porosity column (with
# output.compression) is above it before the last row and at or below it there.
sed 's/duration: 0.06/duration: 0.005/; s/    move_wall: {wall: 1, velocity: \[0, 0, -0.1\]}/    move_wall: {wall: 1, velocity: [0, 0, -0.1]}\n    stop: {porosity: 0.875, wall: 1}/; s/^output: {/output: {compression: {wall: 1}, /' \
  "$base" > "$scratch/porosity.yaml"
"$sqdem" run "$scratch/porosity.yaml" --out "$scratch/porosity" > "$scratch/porosity.log" 2>&1
check "the press stopped at the porosity" grep -Eq "stage 'press': .*wall 1 pressed the bed to porosity 0\.87[0-9]* \(target 0\.875\)" "$scratch/porosity.log"
check "the CSV's porosity crossed 0.875 in the last row" awk -F, '
  NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  { before = last; last = $c["porosity"] }
  END { printf "  porosity: %s then %s\n", before, last; exit !(before > 0.875 && last <= 0.875) }' "$scratch/porosity/porosity.csv"
expect_error "porosity out of range" 1 "'stages\[1\].stop.porosity': must be in \(0, 1\)" \
  "$sqdem" run "$(sed 's/porosity: 0.875/porosity: 1.5/' "$scratch/porosity.yaml" > "$scratch/p15.yaml"; echo "$scratch/p15.yaml")" --out "$scratch/p15"
finish
