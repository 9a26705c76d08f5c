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

# The boundary-element reference: posed particles only, cells an integer in [16, 512], no
# tangential drive; each refused by one message naming the key, nothing written.
reference='"material": {"youngs_modulus": 1e9, "poisson_ratio": 0.3}, "path": {"points": [0, 1e-8]}, "curves": [{"label": "c",'
printf '{%s "geometry": {"radii": [1e-6, 1e-6]}, "law": {"type": "boundary_element"}}]}' "$reference" > "$scratch/reference.json"
expect_error "boundary_element on radii" 1 "curves\[0\].law: boundary_element needs the curve's geometry as 'particles'" \
  "$sqdem" contact "$scratch/reference.json" --out "$out"
pair='{"particles": [{"centre": [0, 0, 0], "quaternion": [1, 0, 0, 0], "a": 1e-6, "b": 1e-6, "c": 1e-6, "n1": 2, "n2": 2},
  {"centre": [0, 0, 2.1e-6], "quaternion": [1, 0, 0, 0], "a": 1e-6, "b": 1e-6, "c": 1e-6, "n1": 2, "n2": 2}]}'
for cells in 8 1000 64.5; do
  printf '{%s "geometry": %s, "law": {"type": "boundary_element", "cells": %s}}]}' "$reference" "$pair" "$cells" > "$scratch/reference.json"
  expect_error "boundary_element cells $cells" 1 "curves\[0\].law: 'cells' .per side of the grid. must be an integer in \[16, 512\]" \
    "$sqdem" contact "$scratch/reference.json" --out "$out"
done
printf '{%s "geometry": %s, "law": {"type": "boundary_element"}}], "tangential": {"points": [0, 1e-9], "friction": 0.3}}' \
  "$reference" "$pair" > "$scratch/reference.json"
expect_error "boundary_element tangential" 1 "curve 'c' is the boundary_element reference .normal only." "$sqdem" contact "$scratch/reference.json" --out "$out"
check "nothing written for the refused references" test ! -e "$out"
finish
