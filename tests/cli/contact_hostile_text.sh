# `sqdem contact` never lets user text reach a script, a shell or a path: hostile titles are
# refused with one message naming 'title' and nothing is written; a plain title is written as is.
. "$(dirname "$0")/lib.sh"
out="$scratch/out"
marker="$scratch/PWNED"
base='"material": {"youngs_modulus": 1e9, "poisson_ratio": 0.3}, "path": {"points": [0, 1e-8, 0]},
  "curves": [{"label": "c", "geometry": {"radii": [1e-6, 1e-6]}, "law": {"type": "elliptic_hertz"}}]'

hostile=(
  "x'\\nsystem('touch $marker')\\nset title 'y"
  "a\\\"b"
  "back\\\\slash"
  "system('touch $marker')"
  "\`touch $marker\`"
  "\$(touch $marker)"
  "@macro"
  "tab\\there"
)
for t in "${hostile[@]}"; do
  printf '{"title": "%s", %s}' "$t" "$base" > "$scratch/hostile.json"
  expect_error "title $t" 1 "'title' must be a string" "$sqdem" contact "$scratch/hostile.json" --out "$out"
  check "nothing written for title $t" test ! -e "$out"
  check "no command ran for title $t" test ! -e "$marker"
done

# Names and labels become file names: path separators, '..' and option-like names are refused.
for n in "../escape" "a/b" ".hidden" "-o"; do
  printf '{"name": "%s", %s}' "$n" "$base" > "$scratch/name.json"
  expect_error "name $n" 1 "'name' may contain only" "$sqdem" contact "$scratch/name.json" --out "$out"
done
printf '{%s}' "$(printf '%s' "$base" | sed 's/"label": "c"/"label": "..\/c"/')" > "$scratch/label.json"
expect_error "label ../c" 1 "'label' must be a string of letters" "$sqdem" contact "$scratch/label.json" --out "$out"
check "nothing written for bad names" test ! -e "$out"

# An output directory with a quote and a space works (no shell parses it), and a plain title
# with punctuation reaches the script verbatim.
printf '{"name": "ok", "title": "Hertz (R = 1 um), 5%% / 10%%: ok!", %s}' "$base" > "$scratch/ok.json"
weird="$scratch/it's a dir"
check "plain title runs" "$sqdem" contact "$scratch/ok.json" --out "$weird"
check "title verbatim in the script" grep -qF "set title 'Hertz (R = 1 um), 5% / 10%: ok!' noenhanced" "$weird/ok.gp"
if command -v gnuplot >/dev/null; then
  check "PNG written" test -s "$weird/ok.png"
  check "no temporary PNG left" test ! -e "$weird/ok.png.tmp"
  # Rerun as the script's header says: it writes ok.png again, not ok.png.tmp.
  rm "$weird/ok.png"
  check "the script rerun by hand" bash -c 'cd "$1" && gnuplot ok.gp' _ "$weird"
  check "its PNG is ok.png" test -s "$weird/ok.png"
  check "and no ok.png.tmp" test ! -e "$weird/ok.png.tmp"
fi

# The laws of the true gap (the boundary-element reference, the true-gap law): posed particles
# only, cells an integer in [16, 512] and [8, 64], no tangential drive; each refused by one
# message naming the key, nothing written.
reference='"material": {"youngs_modulus": 1e9, "poisson_ratio": 0.3}, "path": {"points": [0, 1e-8]}, "curves": [{"label": "c",'
pair='{"particles": [{"centre": [0, 0, 0], "quaternion": [1, 0, 0, 0], "a": 1e-6, "b": 1e-6, "c": 1e-6, "n1": 2, "n2": 2},
  {"centre": [0, 0, 2.1e-6], "quaternion": [1, 0, 0, 0], "a": 1e-6, "b": 1e-6, "c": 1e-6, "n1": 2, "n2": 2}]}'
# boundary_element words its own message; true_gap's is the law registry's (TrueGapLaw::read).
for law in "boundary_element 16 512 8 1000 64.5" "true_gap 8 64 4 100 16.5"; do
  set -- $law
  type=$1 low=$2 high=$3
  if [ "$type" = boundary_element ]; then
    cells_message="'cells' .per side of the grid. must be an integer in \[$low, $high\]"
  else
    cells_message="'cells' must be an integer in \[$low, $high\] .cells per side of the coarse grid."
  fi
  printf '{%s "geometry": {"radii": [1e-6, 1e-6]}, "law": {"type": "%s"}}]}' "$reference" "$type" > "$scratch/reference.json"
  expect_error "$type on radii" 1 "curves\[0\].law: $type needs the curve's geometry as 'particles'" \
    "$sqdem" contact "$scratch/reference.json" --out "$out"
  for cells in $4 $5 $6; do
    printf '{%s "geometry": %s, "law": {"type": "%s", "cells": %s}}]}' "$reference" "$pair" "$type" "$cells" > "$scratch/reference.json"
    expect_error "$type cells $cells" 1 "curves\[0\].law: $cells_message" \
      "$sqdem" contact "$scratch/reference.json" --out "$out"
  done
  printf '{%s "geometry": %s, "law": {"type": "%s"}}], "tangential": {"points": [0, 1e-9], "friction": 0.3}}' \
    "$reference" "$pair" "$type" > "$scratch/reference.json"
  expect_error "$type tangential" 1 "curve 'c' is a law of the true gap .boundary_element or true_gap: normal only." \
    "$sqdem" contact "$scratch/reference.json" --out "$out"
done
# A key the true-gap law does not take (a driver key of the other laws, here) is refused by the registry.
printf '{%s "geometry": %s, "law": {"type": "true_gap", "eccentricity": "exact"}}]}' "$reference" "$pair" > "$scratch/reference.json"
expect_error "true_gap unknown key" 1 "curves\[0\].law: 'eccentricity' unknown key \(allowed: type, and for true_gap: cells, gap_tolerance\)" \
  "$sqdem" contact "$scratch/reference.json" --out "$out"
# gap_tolerance: a fraction of the overlap in [0, 1].
for tolerance in -0.01 1.5; do
  printf '{%s "geometry": %s, "law": {"type": "true_gap", "gap_tolerance": %s}}]}' "$reference" "$pair" "$tolerance" > "$scratch/reference.json"
  expect_error "true_gap gap_tolerance $tolerance" 1 "curves\[0\].law: 'gap_tolerance' must be in \[0, 1\] .the change of the gap across the contact" \
    "$sqdem" contact "$scratch/reference.json" --out "$out"
done
check "nothing written for the refused references" test ! -e "$out"
finish
