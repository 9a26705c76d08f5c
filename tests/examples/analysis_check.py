#!/usr/bin/python3
"""Runs `sqdem analyse` on a particle file and on the same file with its rows reversed, and checks
the analysis (CTest example_analysis_*; docs/electrode_analysis.md):

  analysis_check.py SQDEM SCENE PARTICLES OUTDIR VOXELS

every number of the JSON object present and in its range (porosity and the ratios in (0, 1), a
tortuosity factor >= 1, the network's ratio in (0, 1) where it percolates and 0 where it does
not), the files it names written, and the two orders agreeing: the voxel image does not
depend on the order (bit for bit), the network's solution to the conjugate gradients' tolerance."""
import json
import math
import os
import subprocess
import sys

sqdem, scene, particles, outdir, voxels = sys.argv[1:6]
os.makedirs(outdir, exist_ok=True)
with open(particles) as f:
    lines = f.read().splitlines()
reversed_file = os.path.join(outdir, 'reversed_particles.csv')
with open(reversed_file, 'w') as f:
    f.write('\n'.join([lines[0]] + lines[:0:-1]) + '\n')


def analyse(path, name):
    run = subprocess.run([sqdem, 'analyse', scene, '--particles', path, '--out', os.path.join(outdir, name),
                          '--voxels', voxels], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f'sqdem analyse {path} failed: {run.stderr}')
    return json.loads(run.stdout)


a, b = analyse(particles, 'given'), analyse(reversed_file, 'reversed')
print(json.dumps({k: a[k] for k in ('porosity', 'coordination', 'specific_surface_area_m2_per_m3', 'tortuosity_factor',
                                    'electronic_conductivity_ratio', 'seconds')}))
failures = []
axes = ('x', 'y', 'z')
if not 0.0 < a['porosity'] < 1.0 or abs(a['solid_fraction'] + a['porosity'] - 1.0) > 1e-12:
    failures.append(f"porosity {a['porosity']}, solid fraction {a['solid_fraction']}")
if not a['coordination'] > 0.0 or not a['specific_surface_area_m2_per_m3'] > 0.0:
    failures.append('no contacts or no surface')
if not a['solvers_converged']:
    failures.append('a conjugate-gradient solve did not converge')
for d in axes:
    tau, ratio = a['tortuosity_factor'][d], a['effective_diffusivity_ratio'][d]
    if tau is None or not (tau >= 1.0 and 0.0 < ratio < a['porosity'] and math.isclose(tau, a['porosity'] / ratio, rel_tol=1e-12)):
        failures.append(f'pores along {d}: tau {tau}, D_eff/D0 {ratio}')
    if len(a['voxel_convergence']['tortuosity_factor'][d]) != 2:
        failures.append(f'no convergence study along {d}')
    ratio, percolates = a['electronic_conductivity_ratio'][d], a['network']['percolates'][d]
    if not (0.0 < ratio < 1.0 if percolates else ratio == 0.0 and a['network']['carrying_nodes'][d] == 0):
        failures.append(f'network along {d}: ratio {ratio}, percolates {percolates}')
for f in a['files']:
    if not os.path.getsize(f) > 0:
        failures.append(f'{f} empty')
exact = ('porosity', 'specific_surface_area_m2_per_m3', 'coordination', 'particles')
for key in exact:
    if not math.isclose(a[key], b[key], rel_tol=1e-12):
        failures.append(f'{key} depends on the order: {a[key]} vs {b[key]}')
for d in axes:
    for key, tol in (('tortuosity_factor', 1e-12), ('electronic_conductivity_ratio', 1e-7)):
        if a[key][d] is None or b[key][d] is None or not math.isclose(a[key][d], b[key][d], rel_tol=tol):
            failures.append(f'{key}.{d} depends on the order: {a[key][d]} vs {b[key][d]}')
if failures:
    sys.exit('analysis check failed:\n  ' + '\n  '.join(failures))
print('analysis check passed')
