#!/usr/bin/python3
"""The Table 1 curves as JSON (CTest cli_validate_table1_curves; docs/contact_laws.md, "Blocky
contacts"):

  table1_curve_check.py SQDEM

`sqdem validate table1 --json` with the review's model, elliptic Hertz, the boundary-element
reference and the true-gap law: each prints the three cases at the six overlaps; the Hertz models
are constant in the overlap to 1e-3 (a quadratic gap: the normalised force gamma (Rc/R_vol)^1/2
of the curvatures, 004 Eq. 1), the reference falls with the overlap for the face-to-edge cases 1
and 2 and equals elliptic Hertz for case 3 at the smallest overlap to 3e-3 (a Hertzian gap), the
true-gap law is within 1 % of the reference at every point (issue 30's target: 3 %); an unknown law is
refused naming the allowed ones."""
import json
import subprocess
import sys

sqdem = sys.argv[1]
overlaps = [1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2]


def curves(law):
    run = subprocess.run([sqdem, 'validate', 'table1', '--law', law, '--json'], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f'--law {law} failed ({run.returncode}): {run.stderr}')
    out = json.loads(run.stdout)
    assert out['law'] == law, out['law']
    by_case = {}
    for point in out['cases']:
        by_case.setdefault(point['case'], []).append(point)
    assert sorted(by_case) == [1, 2, 3], sorted(by_case)
    for case, points in by_case.items():
        assert [p['overlap_over_rvol'] for p in points] == overlaps, (law, case)
    return {case: [p['normalised_force'] for p in points] for case, points in by_case.items()}


failures = []
hertz = curves('elliptic_hertz')
for law, values in (('review', curves('review')), ('elliptic_hertz', hertz)):
    for case, forces in values.items():
        if max(forces) / min(forces) - 1.0 > 1e-3:
            failures.append(f'{law} case {case} not constant: {forces}')
reference = curves('boundary_element')
print(json.dumps(reference))
for case in (1, 2):
    forces = reference[case]
    if any(b >= a for a, b in zip(forces, forces[1:])):
        failures.append(f'boundary_element case {case} does not fall with the overlap: {forces}')
if abs(reference[3][0] / hertz[3][0] - 1.0) > 3e-3:
    failures.append(f'boundary_element case 3 at 1e-4: {reference[3][0]} against elliptic Hertz {hertz[3][0]}')
true_gap = curves('true_gap')
for case in (1, 2, 3):
    for overlap, law, ref in zip(overlaps, true_gap[case], reference[case]):
        if abs(law / ref - 1.0) > 0.01:
            failures.append(f'true_gap case {case} at {overlap}: {law} against the reference {ref}')
bad = subprocess.run([sqdem, 'validate', 'table1', '--law', 'hooke'], capture_output=True, text=True)
if bad.returncode != 2 or 'allowed: review, elliptic_hertz, boundary_element, true_gap)' not in bad.stderr:
    failures.append(f'an unknown law: exit {bad.returncode}, {bad.stderr!r}')
if failures:
    sys.exit('\n'.join(failures))
print('Table 1 curves: OK')
