# The example jobs under mpirun (docs/running.md), shortened: at 2 ranks their final particle
# file, whole CSV log and compression curve are, byte for byte, one process's.
#   - the calendering press (examples/nmc_calendering.yaml): a plate pressing the NMC bed
#     through Becker-Kamlah contacts (plastic histories), held and released, with the energy
#     ledger and the compression report;
#   - the roller pass (examples/roller_pass.yaml): a spinning cylinder wall across a periodic
#     direction, lowered into a poured bed and rolled across it.
. "$(dirname "$0")/lib.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1 OMP_WAIT_POLICY=passive
examples="$source_dir/examples"

same_at_two_ranks() {  # NAME SCENE
  local name=$1 scene=$2 stem
  stem=$(basename "$scene" .yaml)
  check "$name: one process" "$sqdem" run "$scene" --threads 1 --out "$scratch/$stem/one" > "$scratch/$stem.one.log"
  check "$name: 2 ranks" timeout 600 mpirun --oversubscribe -np 2 "$sqdem" run "$scene" --threads 1 \
    --out "$scratch/$stem/two" > "$scratch/$stem.two.log"
  for file in "${stem}_final_particles.csv" "$stem.csv" "${@:3}"; do
    check "$name: $file as one process's" cmp -s "$scratch/$stem/one/$file" "$scratch/$stem/two/$file"
  done
}

# The press, shortened: relax 20 us, press 0.3 ms (the plate 3 um into the bed; its 300 MPa stop
# criterion is checked, not reached), hold 10 us, release 0.1 ms.
mkdir -p "$scratch/press"
cp "$examples/nmc_packed_bed.csv" "$scratch/press/"
sed -e '/name: relax/,/viscous_damping/s/duration: 2.0e-4 /duration: 2.0e-5 /' \
    -e '/name: press/,/stop:/s/duration: 2.0e-3/duration: 3.0e-4/' \
    -e '/name: hold/,/duration/s/duration: 5.0e-5/duration: 1.0e-5/' \
    -e '/name: release/,/duration/s/duration: 3.5e-4/duration: 1.0e-4/' "$examples/nmc_calendering.yaml" > "$scratch/press/press.yaml"
check "the press scene was shortened" grep -q "duration: 3.0e-4" "$scratch/press/press.yaml"
same_at_two_ranks "press" "$scratch/press/press.yaml" press_compression.csv
check "press: the plate pressed the bed (peak > 1 MPa)" grep -Eq "peak plate pressure ([1-9]|[1-9][0-9]+)\.[0-9]* MPa" "$scratch/press.two.log"
check "press: some contacts yielded" grep -Eq "[1-9][0-9.]* % of the contacts yielded" "$scratch/press.two.log"

# The roller pass: pour at most 0.1 s, lower as in the example, roll a quarter of the period,
# lift a quarter of the way.
sed -e 's/duration: 0.3 /duration: 0.1 /' -e 's/duration: 0.12/duration: 0.03/' -e 's/duration: 0.05$/duration: 0.0125/' \
  "$examples/roller_pass.yaml" > "$scratch/roller.yaml"
check "the roller scene was shortened" grep -q "duration: 0.03" "$scratch/roller.yaml"
same_at_two_ranks "roller pass" "$scratch/roller.yaml"
check "roller: the roller pressed the bed while rolling" awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
  $3 == "roll" && $c["wall1_fz_N"] > 0 { n++ } END { exit !(n > 0) }' "$scratch/roller/two/roller.csv"
finish
