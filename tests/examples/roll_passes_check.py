#!/usr/bin/python3
"""Checks the passes of a roll example's CSV log (CTest example_nmc_bonded_calendering_roll):

  roll_passes_check.py LOG.csv RADIUS GAP1 GAP2 ...

one pass per gap (m: the roll's axis at gap + radius, to 10 nm: the roll moves in whole steps);
each pass loads the roll (its mean line load over the strip's middle, x = 20-80 um, is positive),
breaks bonds but not all of them, and closes the energy ledger: the work done on the bodies
equals what the dissipations took plus the change of stored and kinetic energy, the ledger's
residual below 1e-3 of the pass's work (docs/output.md, energy columns). Prints the passes (scripts/roll_passes.py)."""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', '..', 'scripts'))
from roll_passes import summary  # noqa: E402

log, radius, gaps = sys.argv[1], float(sys.argv[2]), [float(g) for g in sys.argv[3:]]
with open(log, newline='') as f:
    passes = summary(list(csv.DictReader(f)), radius=radius, middle=(20e-6, 80e-6))
failures = []
if len(passes) != len(gaps):
    failures.append('%d passes, expected %d' % (len(passes), len(gaps)))
for p, gap in zip(passes, gaps):
    e = p['energy']
    print('%s: gap %.2f um, line load %.0f N/m mean, %.0f N/m peak, bonds broken %d, intact %d, work %.3g J, residual %.3g J'
          % (p['stage'], p['gap'] * 1e6, p['mean'], p['peak'], p['broken'], p['intact'], e['work'], e['residual']))
    if abs(p['gap'] - gap) > 1e-8:  # a stage moves the roll in whole steps: 7.7 nm each when lowered
        failures.append('%s: gap %.9g m, expected %.9g' % (p['stage'], p['gap'], gap))
    if not p['mean'] > 0.0:
        failures.append('%s: mean line load %g N/m, expected > 0' % (p['stage'], p['mean']))
    if not (p['broken'] > 0 and p['intact'] > 0):
        failures.append('%s: %d bonds broken, %d intact: expected some of each' % (p['stage'], p['broken'], p['intact']))
    if not (e['work'] > 0.0 and abs(e['residual']) < 1e-3 * e['work']):
        failures.append('%s: ledger residual %g J against the work %g J' % (p['stage'], e['residual'], e['work']))
for failure in failures:
    print('FAILED', failure)
sys.exit(1 if failures else 0)
