# `sqdem run` control on tests/scenes/small_bed.yaml: checkpoints resume bit for bit (mid-stage
# and after SIGINT, and under a scene with other stages) with the step column continuing; an occupied --out is refused and left
# untouched; --overwrite replaces sqdem's files; stale temporaries are removed; foreign,
# truncated and corrupted checkpoints get one clear message and exit 1.
. "$(dirname "$0")/lib.sh"
scene="$source_dir/tests/scenes/small_bed.yaml"
a="$scratch/a"

check "uninterrupted run" "$sqdem" run "$scene" --out "$a" > "$scratch/a.log"
final=$(tail -1 "$a/small_bed.csv")

# The log's columns carry their units; the run plotted it, and `sqdem plot` plots it again.
check "CSV header with units" grep -q "^time_s,step,stage,kinetic_energy_J,contacts,mean_coordination,solid_fraction,between_walls_solid_fraction,bed_height_m,.*,wall0_z_m,wall0_fx_N,wall0_fy_N,wall0_fz_N,wall0_p_Pa," "$a/small_bed.csv"
check "the run wrote its plot" test -s "$a/small_bed_run.png"
rm "$a/small_bed_run.png"
expect_output "sqdem plot" "small_bed_run.png" "$sqdem" plot "$a/small_bed.csv"
check "sqdem plot wrote the PNG" test -s "$a/small_bed_run.png"
expect_error "plot of a file that is not a run log" 1 "is not an sqdem run log" "$sqdem" plot "$a/small_bed_final_particles.csv"
cp "$a/small_bed.csv" "$scratch/it's.csv"
expect_error "plot of a log with a quote in its name" 1 "the log's file name must be letters, digits" "$sqdem" plot "$scratch/it's.csv"
# Particle surfaces: drawn by default up to 20,000 particles; above, not unless asked, and the
# run says so.
sed -e 's/count: 120,/count: 20001,/' -e 's/volume_radius: \[0.4e-3, 0.5e-3\]/volume_radius: 0.04e-3/' -e 's/duration: 0.06/duration: 1.0e-5/' \
  -e 's/duration: 0.02/duration: 1.0e-5/' "$scene" > "$scratch/many.yaml"
expect_output "no surfaces above 20,000 particles by default" "20001 particles: their surfaces are not drawn by default above 20000" \
  "$sqdem" run "$scratch/many.yaml" --out "$scratch/many"
check "... and none written" test ! -e "$scratch/many/many_surfaces.pvd"
check "a small bed's surfaces are written" test -s "$a/small_bed_surfaces.pvd"
cp "$scene" "$scratch/bad name.yaml"
expect_error "a scene file name that cannot name files" 1 "the scene's name .* names the output files: it must be 1-100 letters" "$sqdem" run "$scratch/bad name.yaml" --out "$scratch/bad"
check "nothing written for it" test ! -e "$scratch/bad"

# The final state as a particle file, and a scene that starts from it (a packed bed).
check "final particle file: header and 120 rows" awk -F, 'NR == 1 { ok = ($1 == "material" && NF == 19) } END { exit !(ok && NR == 121) }' \
  "$a/small_bed_final_particles.csv"
mkdir -p "$scratch/restart"
cp "$a/small_bed_final_particles.csv" "$scratch/restart/bed.csv"
sed -e 's|^  - {count: 120.*|  - {file: bed.csv, allow_overlap: true}|' -e '/^stages:/,$d' "$scene" > "$scratch/restart/restart.yaml"
printf 'stages:\n  - {name: relax, duration: 0.002}\noutput: {frames: 1}\n' >> "$scratch/restart/restart.yaml"
check "a scene starts from the final particle file" "$sqdem" run "$scratch/restart/restart.yaml" --out "$scratch/restart/out" > /dev/null
sed 's|allow_overlap: true|allow_overlap: false|' "$scratch/restart/restart.yaml" > "$scratch/restart/strict.yaml"
expect_error "a packed bed without allow_overlap" 1 "bed.csv:[0-9]* overlaps .* set allow_overlap: true" \
  "$sqdem" run "$scratch/restart/strict.yaml" --out "$scratch/restart/strict"

# Mid-stage resume from the periodic checkpoint (every 5000 steps: the last one is in 'pour').
check "resume from the periodic checkpoint" "$sqdem" run "$scene" --resume "$a/small_bed_latest.checkpoint" --out "$a" > /dev/null
check "resumed final row equals the uninterrupted one (step column continues)" \
  test "$(tail -1 "$a/small_bed_from_step10000.csv")" = "$final"
check "resumed CSV starts past step 10000" awk -F, 'NR == 2 { exit !($2 > 10000) }' "$a/small_bed_from_step10000.csv"

# An occupied --out: refused, nothing touched; --overwrite replaces sqdem's own files only.
before=$(cksum < "$a/small_bed.csv")
echo keep > "$a/notes.txt"
echo keep > "$a/small_bed_large.csv"  # another scene's log with the same prefix
expect_error "occupied --out" 1 "already holds .* --overwrite" "$sqdem" run "$scene" --out "$a"
check "refused run left the CSV alone" test "$(cksum < "$a/small_bed.csv")" = "$before"
check "overwrite" "$sqdem" run "$scene" --out "$a" --overwrite > /dev/null
check "overwrite reproduces the run" test "$(tail -1 "$a/small_bed.csv")" = "$final"
check "overwrite keeps other files" test -f "$a/notes.txt" -a -f "$a/small_bed_large.csv"
check "overwrite removed the resumed files of the old run" test ! -e "$a/small_bed_from_step10000.csv"

# SIGINT: finishes the step, writes log and checkpoint, says how to resume, exits 130.
b="$scratch/b"
stale_pid=$(sh -c 'echo $$')
mkdir -p "$b" && echo partial > "$b/small_bed.csv.tmp$stale_pid"
"$sqdem" run "$scene" --out "$b" > "$scratch/b.log" 2> "$scratch/b.err" &
pid=$!
for _ in $(seq 600); do
  [ -f "$b/small_bed.csv" ] && [ "$(wc -l < "$b/small_bed.csv")" -ge 10 ] && break
  sleep 0.05
done
kill -INT "$pid"
wait "$pid"
rc=$?
check "SIGINT exits 130 (got $rc)" test "$rc" -eq 130
check "SIGINT says how to resume" grep -q "resume with: sqdem run .* --resume .*small_bed_latest.checkpoint" "$scratch/b.err"
check "stale temporary removed" test ! -e "$b/small_bed.csv.tmp$stale_pid"
step=$(tail -1 "$b/small_bed.csv" | cut -d, -f2)
check "interrupted resume" "$sqdem" run "$scene" --resume "$b/small_bed_latest.checkpoint" --out "$b" > /dev/null
check "interrupted run resumed to the same final row" test "$(tail -1 "$b/small_bed_from_step$step.csv")" = "$final"

# A new protocol on a checkpointed state (a scene that changes only its stages): the settled bed
# of 'pour' pressed by a scene whose one stage is the first scene's 'press' ends, bit for bit, as
# the first scene did: every contact history kept (a particle file would drop them).
sed '/^  - name: pour/,/^    duration: 0.06/d' "$scene" > "$scratch/press_only.yaml"
check "the press-only scene has one stage" test "$(grep -c -- '- name:' "$scratch/press_only.yaml")" -eq 1
expect_output "a scene with other stages resumes a checkpoint" "under this scene's stages .* from stage 'press'" \
  "$sqdem" run "$scratch/press_only.yaml" --resume "$a/small_bed_after_pour.checkpoint" --out "$scratch/protocol"
step=$(awk -F, 'END { print $2 }' "$a/small_bed.csv")
check "... to the first scene's final state" cmp -s "$a/small_bed_final_particles.csv" \
  "$(ls "$scratch"/protocol/press_only_from_step*_final_particles.csv)"
check "... its step column continuing" test "$(awk -F, 'END { print $2 }' "$scratch"/protocol/press_only_from_step*[0-9].csv)" -eq "$step"

expect_error "a mid-stage checkpoint under other stages" 1 "written in the middle of stage 1, which this scene changes" \
  "$sqdem" run "$scratch/press_only.yaml" --resume "$a/small_bed_latest.checkpoint" --out "$scratch/c"

# Bad checkpoints.
sed 's/youngs_modulus: 1.0e7/youngs_modulus: 2.0e7/' "$scene" > "$scratch/stiffer.yaml"
expect_error "foreign checkpoint: what differs named" 1 "written for another scene \('materials' differ\): a checkpoint resumes under a scene that changes only its 'stages' and 'output'" \
  "$sqdem" run "$scratch/stiffer.yaml" --resume "$a/small_bed_after_pour.checkpoint" --out "$scratch/c"
sed -e 's/youngs_modulus: 1.0e7/youngs_modulus: 2.0e7/' -e 's/seed: \([0-9]*\)/seed: 9\1/' "$scene" > "$scratch/reseeded.yaml"
expect_error "foreign checkpoint: every difference named" 1 "\('seed', 'materials' differ\)" \
  "$sqdem" run "$scratch/reseeded.yaml" --resume "$a/small_bed_after_pour.checkpoint" --out "$scratch/c"
head -c 5000 "$a/small_bed_after_pour.checkpoint" > "$scratch/truncated.checkpoint"
expect_error "truncated checkpoint" 1 "truncated" "$sqdem" run "$scene" --resume "$scratch/truncated.checkpoint" --out "$scratch/c"
cp "$a/small_bed_after_pour.checkpoint" "$scratch/flipped.checkpoint"
printf '\x5a' | dd of="$scratch/flipped.checkpoint" bs=1 seek=4000 conv=notrunc 2>/dev/null
expect_error "corrupted checkpoint" 1 "checksum" "$sqdem" run "$scene" --resume "$scratch/flipped.checkpoint" --out "$scratch/c"
expect_error "directory as checkpoint" 1 "not a checkpoint file" "$sqdem" run "$scene" --resume "$scratch" --out "$scratch/c"
expect_error "scene as checkpoint" 1 "not an sqdem checkpoint" "$sqdem" run "$scene" --resume "$scene" --out "$scratch/c"
check "bad checkpoints created no output" test ! -e "$scratch/c"

# --simd (simd_path.hpp): the small bed made of polydisperse spheres, run contact by contact
# and on the widest path this CPU runs, ends in the same particle file and log, byte for byte;
# a path that does not exist is refused.
sed 's/^  bead: .*/  bead: {volume_radius: [0.4e-3, 0.5e-3]}/' "$scene" > "$scratch/spheres.yaml"
"$sqdem" run "$scratch/spheres.yaml" --simd scalar --out "$scratch/scalar" > "$scratch/scalar.log" 2>&1
"$sqdem" run "$scratch/spheres.yaml" --out "$scratch/widest" > "$scratch/widest.log" 2>&1
check "the run names its kernels' path" grep -Eq "thread\(s\), (baseline|avx2) kernels" "$scratch/widest.log"
check "a bed of spheres in contact" grep -Eq "^final: solid fraction 0\.[3-6].*mean coordination [3-6]\." "$scratch/widest.log"
check "every path, the same particles" cmp "$scratch/scalar/spheres_final_particles.csv" "$scratch/widest/spheres_final_particles.csv"
check "every path, the same log" cmp "$scratch/scalar/spheres.csv" "$scratch/widest/spheres.csv"
expect_error "--simd avx512" 2 "--simd = 'avx512': expected a SIMD path this CPU runs: scalar, baseline" "$sqdem" run "$scene" --simd avx512
finish
