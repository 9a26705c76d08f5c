# Helpers for the command-line tests: each test script is called as
#   bash tests/cli/NAME.sh <path to sqdem> <scratch directory> [source directory]
# and ends with `finish`, which prints 'N passed, N failed' and exits non-zero on a failure.
set -u
sqdem=$1
scratch=$2
source_dir=${3:-}
rm -rf "$scratch" && mkdir -p "$scratch"
passed=0
failed=0

pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

# expect_error NAME EXIT_CODE PATTERN COMMAND...: the command exits with EXIT_CODE and its
# standard error matches the grep -E PATTERN.
expect_error() {
  local name=$1 code=$2 pattern=$3
  shift 3
  local err rc
  err=$("$@" 2>&1 >/dev/null)
  rc=$?
  if [ "$rc" -ne "$code" ]; then
    fail "$name: exit $rc, expected $code; stderr: $err"
  elif ! printf '%s' "$err" | grep -qE -- "$pattern"; then
    fail "$name: stderr does not match /$pattern/: $err"
  else
    pass
  fi
}

# expect_output NAME PATTERN COMMAND...: the command succeeds and its standard output matches
# the grep -E PATTERN.
expect_output() {
  local name=$1 pattern=$2
  shift 2
  local out
  if ! out=$("$@" 2>&1); then
    fail "$name: exit non-zero: $out"
  elif ! printf '%s' "$out" | grep -qE -- "$pattern"; then
    fail "$name: output does not match /$pattern/: $out"
  else
    pass
  fi
}

# check NAME COMMAND...: the command succeeds.
check() {
  local name=$1
  shift
  if "$@"; then pass; else fail "$name"; fi
}

finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
