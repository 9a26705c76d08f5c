#!/usr/bin/python3
"""Per pass of a roll over a coating, from the CSV log of sqdem run (the roll examples,
docs/examples.md): the roll's gap, its line load, the bonds broken and where the roll's work went.

  scripts/roll_passes.py LOG.csv --radius R [--wall W] [--depth LY] [--middle LO HI]

A pass is a stage whose name starts with 'pass'. The roll is wall W (default 3), a cylinder of
radius R (m) along y; the gap is its axis height wall<W>_z_m minus R. Line load: the force the
coating exerts on the roll, wall<W>_fz_N, over the box's depth LY along the axis (m, default
100 um), in N/m: its mean over the rows where the axis is within LO <= x <= HI (m; default every
row of the pass) and its peak. Bonds: broken during the pass (bonds_broken), intact at its end.
With output.energy, the energy ledger's increments over the pass (J): the work the walls did on
the bodies and what took it: tangential sliding, normal damping, plasticity, the bonds' dashpots
and breakage, a background drag; and the residual."""
import argparse
import csv
import sys

LEDGER = (('work', 'work_bodies_J'), ('sliding', 'tangential_dissipation_J'),
          ('damping', 'damping_dissipation_J'), ('plastic', 'plastic_dissipation_J'),
          ('bonds', 'bond_dissipation_J'), ('drag', 'drag_dissipation_J'),
          ('residual', 'energy_residual_J'))


def passes(rows):
    """The rows of each pass stage, in order, with the row before it (the pass's start)."""
    out = []
    for i, row in enumerate(rows):
        if not row['stage'].startswith('pass'):
            continue
        if i == 0 or rows[i - 1]['stage'] != row['stage']:
            out.append((row['stage'], rows[i - 1] if i > 0 else row, []))
        out[-1][2].append(row)
    return out


def summary(rows, wall=3, radius=0.0, depth=100e-6, middle=None):
    """One dict per pass: stage, gap (m), mean and peak line load (N/m), rows averaged, bonds
    broken in the pass and intact at its end (None without bonds), energy increments (J)."""
    w = 'wall%d_' % wall
    ledger = [(name, column) for name, column in LEDGER if column in rows[0]]
    out = []
    for stage, before, pass_rows in passes(rows):
        inside = [r for r in pass_rows if middle is None or middle[0] <= float(r[w + 'x_m']) <= middle[1]]
        loads = [float(r[w + 'fz_N']) / depth for r in inside]
        end = pass_rows[-1]
        bonded = 'bonds' in end
        out.append({'stage': stage, 'gap': float(end[w + 'z_m']) - radius,
                    'mean': sum(loads) / len(loads) if loads else float('nan'), 'rows': len(loads),
                    'peak': max(float(r[w + 'fz_N']) for r in pass_rows) / depth,
                    'broken': int(end['bonds_broken']) - int(before['bonds_broken']) if bonded else None,
                    'intact': int(end['bonds']) if bonded else None,
                    'energy': {name: float(end[c]) - float(before[c]) for name, c in ledger}})
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('log')
    parser.add_argument('--radius', type=float, required=True, help='the roll radius R (m)')
    parser.add_argument('--wall', type=int, default=3, help='the roll wall index (default 3)')
    parser.add_argument('--depth', type=float, default=100e-6, help='box depth along the axis (m)')
    parser.add_argument('--middle', type=float, nargs=2, metavar=('LO', 'HI'), help='axis x range (m)')
    args = parser.parse_args()
    with open(args.log, newline='') as f:
        rows = list(csv.DictReader(f))
    if not rows or 'wall%d_fz_N' % args.wall not in rows[0]:
        sys.exit('%s: no column wall%d_fz_N (is wall %d the roll?)' % (args.log, args.wall, args.wall))
    found = summary(rows, args.wall, args.radius, args.depth, args.middle)
    if not found:
        sys.exit('%s: no stage named pass...' % args.log)
    for p in found:
        line = '%s: gap %.2f um, line load mean %.0f N/m (%d rows), peak %.0f N/m' % (
            p['stage'], p['gap'] * 1e6, p['mean'], p['rows'], p['peak'])
        if p['intact'] is not None:
            line += ', bonds broken %d, intact %d' % (p['broken'], p['intact'])
        print(line)
        if p['energy']:
            work = p['energy'].get('work', 0.0)
            shares = ', '.join('%s %.3g J (%.1f %%)' % (name, value, 100 * value / work if work else float('nan'))
                               for name, value in p['energy'].items() if name != 'work')
            print('  energy: work %.3g J; %s' % (work, shares))


if __name__ == '__main__':
    main()
