# Help and version: every command answers --help / -h with its own usage section (and does not
# take the flag for a file or an unknown option), `sqdem --version` prints the project version.
. "$(dirname "$0")/lib.sh"

for command in run plot analyse validate geometry sticking-velocity contact; do
  for flag in --help -h; do
    expect_output "$command $flag" "^usage: sqdem" "$sqdem" "$command" "$flag"
    expect_output "$command $flag names the command" "^  $command " "$sqdem" "$command" "$flag"
  done
done
# --help after other arguments still asks for help (nothing is run, nothing written).
expect_output "run scene --help" "--threads N" "$sqdem" run "$scratch/missing.yaml" --help
check "run --help wrote nothing" test ! -e "$scratch/out"
expect_output "run --help states the default thread count" "default: OMP_NUM_THREADS if set, otherwise one per core" \
  "$sqdem" run --help

version=$(sed -n 's/^project(sqdem VERSION \([0-9.]*\).*/\1/p' "$source_dir/CMakeLists.txt")
expect_output "--version" "^sqdem $version\$" "$sqdem" --version
expect_output "version" "^sqdem $version\$" "$sqdem" version
expect_output "help lists version" "version, --version" "$sqdem" help
expect_error "unknown command lists the commands" 2 "allowed: run, plot, analyse, validate, geometry, sticking-velocity, contact, help, version" \
  "$sqdem" frobnicate
finish
