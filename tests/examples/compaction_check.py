#!/usr/bin/python3
"""Checks the presses of a compaction example's run summary (CTest example_nmc_cbd_calendering):

  sqdem run SCENE | compaction_check.py P1 P2 ...

one press per target pressure P (Pa), in order, each peak within [P, 1.02 P] (a stop ends the
press at the first step at or above P); each press compacts the coating and lets it spring back
part of the way (porosity at the peak < after < before); a higher pressure leaves a denser
coating, under load and after (porosity strictly decreasing from press to press); Meyer et al.'s
compaction law (J. Mater. Process. Technol. 249, 2017: eps = eps_min + (eps_0 - eps_min)
exp(-p / gamma_c)) fitted with eps_min < eps_0, gamma_c > 0 and an rms residual below 0.005; every
contact resolved, no deep overlap where the scene does not expect them, and some where it does
(the carbon-binder pairs' `deep_overlaps: expected`: counted apart, not fatal)."""
import re
import sys

targets = [float(p) for p in sys.argv[1:]]
text = sys.stdin.read()
number = r'([-0-9.e+]+)'
presses = [tuple(float(v) for v in m) for m in re.findall(
    r'compression \d+: peak plate pressure ' + number + r' MPa; coating thickness before ' + number + r' um \(porosity '
    + number + r'\), at the peak ' + number + r' um \(' + number + r'\), after ' + number + r' um \(' + number + r'\)', text)]
fit = re.search(r'eps_min ' + number + r', eps_0 ' + number + r', gamma_c ' + number + r' MPa, rms residual ' + number, text)
expected = re.search(r'deep_overlaps: expected\): (\d+) contact-steps', text)

failures = []
if '0 unresolved, 0 deep overlaps' not in text:
    failures.append("the summary does not say '0 unresolved, 0 deep overlaps'")
if not expected or int(expected.group(1)) == 0:
    failures.append('no deep overlaps counted where the scene expects them')
if len(presses) != len(targets):
    failures.append('%d presses, expected %d' % (len(presses), len(targets)))
for k, ((peak, _, before, _, under, _, after), target) in enumerate(zip(presses, targets)):
    print('press %d: peak %.2f MPa, porosity before %.4f, at the peak %.4f, after %.4f' % (k + 1, peak, before, under, after))
    if not target <= peak * 1e6 <= 1.02 * target:
        failures.append('press %d: peak %.4g MPa, target %.4g MPa' % (k + 1, peak, target * 1e-6))
    if not under < after < before:
        failures.append('press %d: porosity before %.4f, at the peak %.4f, after %.4f' % (k + 1, before, under, after))
for k in range(1, len(presses)):
    if not (presses[k][4] < presses[k - 1][4] and presses[k][6] < presses[k - 1][6]):
        failures.append('press %d left the coating no denser than press %d' % (k + 1, k))
if not fit:
    failures.append('no compaction fit printed')
else:
    eps_min, eps_0, gamma_c, rms = (float(v) for v in fit.groups())
    print('Meyer fit: eps_min %.4f, eps_0 %.4f, gamma_c %.4g MPa, rms residual %.4f' % (eps_min, eps_0, gamma_c, rms))
    if not (eps_min < eps_0 and gamma_c > 0.0 and rms < 0.005):
        failures.append('compaction fit eps_min %g, eps_0 %g, gamma_c %g MPa, rms %g' % (eps_min, eps_0, gamma_c, rms))
for f in failures:
    print('FAILED:', f)
sys.exit(1 if failures else 0)
