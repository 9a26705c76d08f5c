# Impossible, mistyped and hostile scenes and options: one message naming the file, the key and
# what is allowed, exit 1 (2 for usage), and no output directory created. Runs that go wrong
# numerically stop with the likely cause and exit 3.
. "$(dirname "$0")/lib.sh"
base="$source_dir/tests/scenes/small_bed.yaml"
out="$scratch/out"

# variant NAME SED-EXPRESSION: the small bed scene with one edit.
variant() { sed "$2" "$base" > "$scratch/$1.yaml"; echo "$scratch/$1.yaml"; }
refused() {  # refused NAME PATTERN SCENE
  expect_error "$1" 1 "$2" "$sqdem" run "$3" --out "$out"
  check "$1: no output" test ! -e "$out"
  rm -rf "$out"
}

# Time step and stage length (issue items 3, 4, 8).
refused "time_step 1000" "'time_step': 1000 s is .* at most 5 x" "$(variant dt1000 's/^time_step_fraction: 0.2/time_step: 1000/')"
refused "E = 1e300 with an explicit step" "'time_step'.*at most 5 x" \
  "$(variant e300 's/^time_step_fraction: 0.2/time_step: 1.0e-6/; s/youngs_modulus: 1.0e7/youngs_modulus: 1.0e300/')"
refused "E = 142 Pa (forgot e9)" "'stages\[0\].duration' \(stage 'pour'\): .* shorter than one step" \
  "$(variant e142 's/youngs_modulus: 1.0e7/youngs_modulus: 142/; s/duration: 0.06/duration: 1.0e-4/')"
refused "duration 1e20" "'stages\[0\].duration'.*more than 1e12 steps" "$(variant long 's/duration: 0.06/duration: 1.0e+20/')"
refused "time_step 1e-30" "more than 1e12 steps" "$(variant tiny 's/^time_step_fraction: 0.2/time_step: 1.0e-30/')"
refused "density 1e-300" "more than 1e12 steps" "$(variant light 's/density: 2500/density: 1.0e-300/')"

# Stage names go into CSV rows and file names (item 6).
for name in '"a,b"' '"a\\nb"' '"x/../../../escape"' '".hidden"' '"-x"'; do
  refused "stage name $name" "stage.yaml:[0-9]+: 'stages\[0\].name': must be 1-64 letters" "$(variant stage "s|name: pour|name: $name|")"
done
refused "duplicate stage names" "'stages\[1\].name': 'pour' names an earlier stage" "$(variant twice 's/name: press/name: pour/')"

# Impossible geometry and unit slips (item 8).
refused "periodic box narrower than two reaches" "periodic length along x, 0.002 m, must be at least twice" \
  "$(variant narrow 's/hi: \[6.0e-3, 6.0e-3, 12.0e-3\]/hi: [2.0e-3, 6.0e-3, 12.0e-3]/; s/hi: \[6.0e-3, 6.0e-3, 11.0e-3\]/hi: [2.0e-3, 6.0e-3, 11.0e-3]/; s/count: 120/count: 10/')"
refused "insert region outside the domain" "'insert\[0\].region': reaches outside the domain along z" \
  "$(variant outside 's/hi: \[6.0e-3, 6.0e-3, 11.0e-3\]/hi: [6.0e-3, 6.0e-3, 20.0e-3]/')"
refused "particle larger than the box" "insert\[0\]: a particle of bounding diameter .* does not fit the domain" \
  "$(variant huge 's/volume_radius: \[0.4e-3, 0.5e-3\]/volume_radius: [0.4, 0.5]/')"
refused "duplicate key" "dupkey.yaml:[0-9]+: 'materials.glass.density': given twice" \
  "$(variant dupkey 's/density: 2500,/density: 2500, density: 5000,/')"
refused "aspect_b -1" "aspectb.yaml:[0-9]+: 'shapes.bead.aspect_b': must be > 0" "$(variant aspectb 's/aspect_b: \[0.7, 1.0\]/aspect_b: -1/')"
refused "directory as scene" "is a directory, not a scene file" "$scratch"
refused "energy ledger with a law that states no stored energy" \
  "'output.energy': the energy ledger needs every interaction's normal law to state its stored elastic energy .*interactions\[0\] uses haervig_jkr" \
  "$(variant ledger 's/  - materials: \[glass, glass\]/  - {materials: [glass, glass], normal: haervig_jkr, surface_energy: 0.01}/; s/^output: {frames: 4,/output: {energy: true, frames: 4,/')"
refused "compression plate facing up" "'output.compression.wall': the pressing plate must be a plane facing -z" \
  "$(variant plate_up 's/^output: {frames: 4,/output: {compression: {wall: 0}, frames: 4,/')"
refused "compression without a floor" "'output.compression.wall': needs a floor to press against" \
  "$(variant no_floor 's/^output: {frames: 4,/output: {compression: {wall: 1}, frames: 4,/; s/normal: \[0, 0, 1\], material/normal: [1, 0, 0], material/')"
# Mesh walls (issue 13): the STL file relative to the scene, its keys.
printf 'solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n' > "$scratch/tri.stl"
echo "not an stl file" > "$scratch/garbage.stl"
refused "mesh file missing" "'walls\[0\].mesh': cannot open '.*nothere.stl' \(paths are relative to the scene file\)" \
  "$(variant mesh_missing 's/{point: \[0, 0, 0\], normal: \[0, 0, 1\], material: glass}/{point: [0, 0, 0], mesh: nothere.stl, material: glass}/')"
refused "mesh file not STL" "'walls\[0\].mesh': .*garbage.stl" \
  "$(variant mesh_garbage 's/{point: \[0, 0, 0\], normal: \[0, 0, 1\], material: glass}/{point: [0, 0, 0], mesh: garbage.stl, material: glass}/')"
refused "mesh with a spin" "'walls\[0\].spin': belongs to a cylinder \(axis\), not a mesh" \
  "$(variant mesh_spin 's/{point: \[0, 0, 0\], normal: \[0, 0, 1\], material: glass}/{point: [0, 0, 0], mesh: tri.stl, spin: 3, material: glass}/')"
refused "angular velocity on a plane" "'walls\[0\].angular_velocity': belongs to a mesh; a plane does not rotate" \
  "$(variant plane_turn 's/{point: \[0, 0, 0\], normal: \[0, 0, 1\], material: glass}/{point: [0, 0, 0], normal: [0, 0, 1], angular_velocity: [0, 0, 1], material: glass}/')"
refused "angular velocity on a cylinder" "'walls\[1\].angular_velocity': belongs to a mesh; a cylinder turns about its axis by spin" \
  "$(variant cylinder_turn 's/{point: \[0, 0, 12.0e-3\], normal: \[0, 0, -1\], material: glass}/{point: [3.0e-3, 0, 12.0e-3], axis: [0, 1, 0], radius: 1.0e-3, angular_velocity: [0, 1, 0], material: glass}/')"
refused "mesh and normal" "'walls\[0\]': needs exactly one of normal .* or mesh: file.stl" \
  "$(variant mesh_normal 's/{point: \[0, 0, 0\], normal: \[0, 0, 1\], material: glass}/{point: [0, 0, 0], normal: [0, 0, 1], mesh: tri.stl, material: glass}/')"
refused "scale on a plane" "'walls\[0\].scale': belongs to a mesh wall" \
  "$(variant plane_scale 's/{point: \[0, 0, 0\], normal: \[0, 0, 1\], material: glass}/{point: [0, 0, 0], normal: [0, 0, 1], scale: 0.001, material: glass}/')"
refused "mesh scale 0" "'walls\[0\].scale': must be > 0" \
  "$(variant mesh_scale 's/{point: \[0, 0, 0\], normal: \[0, 0, 1\], material: glass}/{point: [0, 0, 0], mesh: tri.stl, scale: 0, material: glass}/')"
refused "cylinder ends without a length" "'walls\[1\].ends': belongs to a finite cylinder: give its length" \
  "$(variant ends_infinite 's/{point: \[0, 0, 12.0e-3\], normal: \[0, 0, -1\], material: glass}/{point: [3.0e-3, 0, 12.0e-3], axis: [0, 1, 0], radius: 1.0e-3, ends: flat, material: glass}/')"
refused "cylinder ends square" "'walls\[1\].ends': must be flat or rounded" \
  "$(variant ends_square 's/{point: \[0, 0, 12.0e-3\], normal: \[0, 0, -1\], material: glass}/{point: [3.0e-3, 0, 12.0e-3], axis: [0, 1, 0], radius: 1.0e-3, length: 4.0e-3, ends: square, material: glass}/')"
expect_error "--out twice" 2 "'--out' is given twice" "$sqdem" run "$base" --out "$out" --out "$out"

# A domain in m with particles in um runs (the cell grid adapts) and says so.
sparse=$(variant sparse 's/volume_radius: \[0.4e-3, 0.5e-3\]/volume_radius: [0.4e-6, 0.5e-6]/; s/duration: 0.06/duration: 1.0e-6/; s/duration: 0.02/duration: 1.0e-6/')
expect_error "sparse domain warns" 0 "fill .* of the domain's volume; are 'domain' and 'shapes' both in m" "$sqdem" run "$sparse" --out "$scratch/sparse"

# A run that blows up stops with the cause and exit 3, its log written (item 3).
blowup=$(variant blowup 's/^time_step_fraction: 0.2/time_step_fraction: 1.0/; s/gravity: \[0, 0, -9.81\]/gravity: [0, 0, -1.0e4]/')
expect_error "runaway energy" 3 "numerical trouble at step [0-9]+ .*runaway energy" "$sqdem" run "$blowup" --out "$scratch/blowup"
expect_error "runaway names the cause" 3 "Likely cause: the time step .* x the Rayleigh time" \
  "$sqdem" run "$blowup" --out "$scratch/blowup" --overwrite
check "runaway: log rows kept" test "$(wc -l < "$scratch/blowup/blowup.csv")" -ge 3

# Other commands (item 9).
expect_error "JSON number overflow" 1 "a number out of range" sh -c "echo '{\"particles\": [1e400]}' | \"$sqdem\" geometry -"
expect_error "directory as JSON" 1 "is a directory, not a JSON file" "$sqdem" geometry "$scratch"
sv="--density 1350 --youngs-modulus 1.2e9 --poisson-ratio 0.33 --wall-youngs-modulus 166e9 --wall-poisson-ratio 0.28 --work-of-adhesion 0.24 --yield-pressure 30e6"
# sqdem analyse: wrong arguments (exit 2) and wrong files (exit 1) are named, nothing is written.
analysed="$source_dir/examples/nmc_calendering.yaml"
bed="$source_dir/examples/nmc_packed_bed.csv"
expect_error "analyse hex voxels" 2 "'--voxels' takes a whole number in \\[4, 256\\], not '0x10'" \
  "$sqdem" analyse "$analysed" --particles "$bed" --voxels 0x10 --out "$scratch/analysis_hex"
expect_error "analyse repeated option" 2 "'--particles' is given twice" \
  "$sqdem" analyse "$analysed" --particles "$bed" --particles "$bed" --out "$scratch/analysis_twice"
expect_error "analyse missing particle file" 1 "missing_bed.csv" \
  "$sqdem" analyse "$analysed" --particles "$scratch/missing_bed.csv" --out "$scratch/analysis_missing"
sed 's/^nmc,/glass,/' "$bed" > "$scratch/glass_bed.csv"
expect_error "analyse unknown material" 1 "glass_bed.csv:2: 'material'" \
  "$sqdem" analyse "$analysed" --particles "$scratch/glass_bed.csv" --out "$scratch/analysis_glass"
check "analyse wrote nothing on errors" test ! -e "$scratch/analysis_hex" -a ! -e "$scratch/analysis_twice" -a ! -e "$scratch/analysis_glass"
expect_error "sticking-velocity radius 1e-300" 1 "option --radius = '1e-300': expected particle radius R \(m\), in \[1e-9, 1\]" \
  "$sqdem" sticking-velocity --radius 1e-300 $sv
expect_error "sticking-velocity repeated option" 1 "option --radius is given twice" \
  "$sqdem" sticking-velocity --radius 2e-6 --radius 3e-6 $sv
expect_error "sticking-velocity hex" 1 "option --density = '0x10'" \
  "$sqdem" sticking-velocity --radius 2e-6 $(echo "$sv" | sed 's/--density 1350/--density 0x10/')
far='{"material": {"youngs_modulus": 1e9, "poisson_ratio": 0.3}, "path": {"points": [0, 9, 0], "unit": "m", "steps": 5},
 "curves": [{"label": "c", "geometry": {"particles": [{"a": 5e-6, "b": 5e-6, "c": 5e-6, "centre": [0, 0, 0]},
 {"a": 5e-6, "b": 5e-6, "c": 5e-6, "centre": [1e-5, 0, 0]}]}, "law": {"type": "elliptic_hertz"}}]}'
echo "$far" > "$scratch/far.json"
expect_error "contact with detector failures" 1 "could not resolve.*--allow-detector-failures" \
  "$sqdem" contact "$scratch/far.json" --out "$scratch/far"
finish
