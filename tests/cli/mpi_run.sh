# `sqdem run` under mpirun (docs/running.md) on tests/scenes/decomposed_bed.yaml (120 particles of
# four shapes poured on a floor, periodic in x and y): at 2 and 3 ranks, and 2 ranks x 2 threads,
# the final particle file and the whole CSV log are, byte for byte, one process's; a checkpoint
# written at one rank count resumes at another to the same final state; SIGUSR1 to mpirun stops
# every rank at the same step with one checkpoint; each frame is a .pvtp over the ranks' pieces;
# an error met on rank 0 alone (the output directory) stops every rank with one message.
. "$(dirname "$0")/lib.sh"
# Open MPI refuses root without these, and more ranks than cores without --oversubscribe.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1 OMP_WAIT_POLICY=passive
mpi() { local ranks=$1; shift; timeout 300 mpirun --oversubscribe -np "$ranks" "$@"; }
sed 's/log_every: 1000}/log_every: 1000, checkpoint_every_steps: 2500}/' "$source_dir/tests/scenes/decomposed_bed.yaml" \
  > "$scratch/bed.yaml"
scene="$scratch/bed.yaml"
same_run() {  # NAME DIR: DIR's final particle file and log are the one-process run's
  check "$1: final particle file as one process's" cmp -s "$scratch/one/bed_final_particles.csv" "$2/bed_final_particles.csv"
  check "$1: CSV log as one process's" cmp -s "$scratch/one/bed.csv" "$2/bed.csv"
}

check "one process" "$sqdem" run "$scene" --threads 1 --out "$scratch/one" > "$scratch/one.log"
expect_output "2 ranks: the first line says so" "^sqdem run: .*: 120 particles, .* 2 rank\(s\) x 1 thread\(s\)" \
  mpi 2 "$sqdem" run "$scene" --threads 1 --out "$scratch/r2"
same_run "2 ranks" "$scratch/r2"
check "3 ranks" mpi 3 "$sqdem" run "$scene" --threads 1 --out "$scratch/r3" > "$scratch/r3.log"
same_run "3 ranks" "$scratch/r3"
check "2 ranks x 2 threads" mpi 2 "$sqdem" run "$scene" --threads 2 --out "$scratch/r2t2" > "$scratch/r2t2.log"
same_run "2 ranks x 2 threads" "$scratch/r2t2"
check "rank 0 alone prints: one summary" test "$(grep -c '^summary:' "$scratch/r3.log")" -eq 1
check "the summary gives the load imbalance" grep -qE "^ranks: 3; load imbalance .* [0-9.]+ at the last build" "$scratch/r3.log"

# VTK output: a .pvtp per frame over the ranks' pieces, listed in the .pvd; the walls from rank 0.
frame="$scratch/r3/bed_particles_00002.pvtp"
check "a .pvtp per frame, listed in the .pvd" grep -q 'file="bed_particles_00002.pvtp"' "$scratch/r3/bed_particles.pvd"
check "the last frame lists every rank's piece" test "$(grep -c '<Piece Source="bed_particles_00002_[0-2].vtp"/>' "$frame")" -eq 3
for k in 0 1 2; do check "piece $k written" test -s "$scratch/r3/bed_particles_00002_$k.vtp"; done
check "the pieces hold 120 particles" test "$(cat "$scratch"/r3/bed_particles_00002_?.vtp | grep -ao 'NumberOfPoints="[0-9]*"' |
  awk -F'"' '{ n += $2 } END { print n }')" -eq 120
check "walls: one .vtp per frame" test -s "$scratch/r3/bed_walls_00002.vtp"

# Checkpoints at any rank count: the 2 ranks' checkpoint at step 5000 resumed at 3 ranks and in
# one process, and one process's at 2 ranks.
resume() {  # NAME RANKS CHECKPOINT DIR
  if [ "$2" -eq 1 ]; then
    check "$1" "$sqdem" run "$scene" --threads 1 --resume "$3" --out "$4" > /dev/null
  else
    check "$1" mpi "$2" "$sqdem" run "$scene" --threads 1 --resume "$3" --out "$4" > /dev/null
  fi
  check "$1: the same final particles" cmp -s "$scratch/one/bed_final_particles.csv" "$4/bed_from_step5000_final_particles.csv"
  check "$1: the same last log row" test "$(tail -1 "$4/bed_from_step5000.csv")" = "$(tail -1 "$scratch/one/bed.csv")"
}
resume "2 ranks' checkpoint resumed at 3 ranks" 3 "$scratch/r2/bed_latest.checkpoint" "$scratch/r2"
resume "2 ranks' checkpoint resumed in one process" 1 "$scratch/r2/bed_latest.checkpoint" "$scratch/r2to1"
resume "one process's checkpoint resumed at 2 ranks" 2 "$scratch/one/bed_latest.checkpoint" "$scratch/one"

# SIGUSR1 to mpirun (passed on to every rank; SIGTERM would be followed by SIGKILL a second
# later): one stop, at one step, with a checkpoint that resumes to the uninterrupted run's final
# state.
sed 's/duration: 0.04}/duration: 0.2}/' "$scene" > "$scratch/long.yaml"
check "uninterrupted long run" "$sqdem" run "$scratch/long.yaml" --threads 1 --out "$scratch/long1" > /dev/null
mpirun --oversubscribe -np 2 "$sqdem" run "$scratch/long.yaml" --threads 1 --out "$scratch/long2" \
  > "$scratch/long2.log" 2> "$scratch/long2.err" &
launcher=$!
(sleep 300 && kill -KILL "$launcher") > /dev/null 2>&1 &  # a watchdog (holding no pipe of ctest's)
watchdog=$!
for _ in $(seq 600); do  # until the log has rows past step 2000
  [ "$({ wc -l < "$scratch/long2/long.csv"; } 2> /dev/null || echo 0)" -ge 4 ] && break
  sleep 0.1
done
kill -USR1 "$launcher"
wait "$launcher"
status=$?
kill "$watchdog" 2> /dev/null
check "SIGUSR1: the run stopped with an error code" test "$status" -ne 0
check "SIGUSR1: one message, how to resume" test "$(grep -c "stopped (SIGUSR1) at step" "$scratch/long2.err")" -eq 1
step=$(sed -n 's/.*stopped (SIGUSR1) at step \([0-9]*\) .*/\1/p' "$scratch/long2.err")
check "SIGUSR1: resumed at 3 ranks" mpi 3 "$sqdem" run "$scratch/long.yaml" --threads 1 \
  --resume "$scratch/long2/long_latest.checkpoint" --out "$scratch/long2" > /dev/null
check "SIGUSR1: the same final particles" cmp -s "$scratch/long1/long_final_particles.csv" \
  "$scratch/long2/long_from_step${step}_final_particles.csv"

# An error rank 0 meets alone: an --out that is a file. One message, every rank exits.
touch "$scratch/a_file"
expect_error "an --out that is a file" 1 "a_file: --out is not a directory" \
  mpi 2 "$sqdem" run "$scene" --out "$scratch/a_file"
check "one message for it" test "$(mpi 2 "$sqdem" run "$scene" --out "$scratch/a_file" 2>&1 | grep -c 'not a directory')" -eq 1
sed 's/restitution: 0.5/restitution: 5/' "$scene" > "$scratch/bad.yaml"
expect_error "a wrong scene" 1 "bad.yaml:[0-9]+: 'materials.glass.restitution': must be in \(0, 1\]" \
  mpi 2 "$sqdem" run "$scratch/bad.yaml" --out "$scratch/bad"
check "one message for it" test "$(mpi 2 "$sqdem" run "$scratch/bad.yaml" --out "$scratch/bad" 2>&1 | grep -c 'restitution')" -eq 1
finish
