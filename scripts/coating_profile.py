#!/usr/bin/python3
"""Thickness and solid fraction of a coating along x, from particle frames written by sqdem run
(<name>_particles_NNNNN.vtp: points, semi_axes, quaternion; read with VTK's Python, Debian's
python3-vtk9), for scenes without a plate (the roll section).

  scripts/coating_profile.py FIRST.vtp [MORE.vtp ...] LAST.vtp [--bins LO HI WIDTH] [--depth LY]

Per x bin (default 0 to 300 um in 25 um bins; m on the command line): the bed's top surface,
the mean over a 10 um grid in y of the highest particle top in each cell (a particle's top is its
centre's z plus its support along z), and the solid fraction below it (the volumes of the
particles centred in the bin over bin width x depth LY (default 100 um) x top). With two or more
frames it prints, per bin and averaged over the bins, the top in the first frame (before), its
lowest over all frames (under the roll), in the last frame (after), springback (after - lowest) /
lowest and permanent compression (before - after) / before."""
import argparse
import math

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def arrays(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    tuples = lambda array: [array.GetTuple(i) for i in range(array.GetNumberOfTuples())]
    out = {'position': tuples(data.GetPoints().GetData())}
    for name in ('semi_axes', 'quaternion'):
        out[name] = tuples(data.GetPointData().GetArray(name))
    return out


def profile(path, lo, hi, width, depth):
    a = arrays(path)
    particles = []
    for p, s, (w, x, y, z) in zip(a['position'], a['semi_axes'], a['quaternion']):
        row = (2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y))  # world z of the body axes
        top = p[2] + math.sqrt(sum((r * e) ** 2 for r, e in zip(row, s)))
        particles.append((p[0], p[1], top, 4.0 / 3.0 * math.pi * s[0] * s[1] * s[2]))
    bins = []
    for k in range(int(round((hi - lo) / width))):
        x0 = lo + k * width
        inside = [q for q in particles if x0 <= q[0] < x0 + width]
        cells = [max((q[2] for q in inside if j * 10e-6 <= q[1] < (j + 1) * 10e-6), default=None)
                 for j in range(int(round(depth / 10e-6)))]
        tops = [c for c in cells if c is not None]
        top = sum(tops) / len(tops)
        bins.append((x0 + 0.5 * width, top, sum(q[3] for q in inside) / (width * depth * top)))
    return bins


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('frames', nargs='+')
    parser.add_argument('--bins', nargs=3, type=float, default=[0.0, 300e-6, 25e-6], metavar=('LO', 'HI', 'WIDTH'))
    parser.add_argument('--depth', type=float, default=100e-6)
    args = parser.parse_args()
    profiles = [profile(f, *args.bins, args.depth) for f in args.frames]
    for path, bins in zip(args.frames, profiles):
        print(path)
        for x, top, phi in bins:
            print('  x %7.1f um  top %7.2f um  solid fraction %.3f' % (x * 1e6, top * 1e6, phi))
    if len(profiles) < 2:
        return
    rows = []
    for k, (x, before, phi0) in enumerate(profiles[0]):
        lowest = min(p[k][1] for p in profiles)
        after, phi1 = profiles[-1][k][1], profiles[-1][k][2]
        rows.append((before, lowest, after, phi0, phi1))
    mean = [sum(r[i] for r in rows) / len(rows) for i in range(5)]
    print('over the bins: top %.1f um before, %.1f um at its lowest, %.1f um after: springback %.1f %%, permanent '
          'compression %.1f %%; solid fraction %.3f -> %.3f' % (mean[0] * 1e6, mean[1] * 1e6, mean[2] * 1e6,
                                                                 100 * (mean[2] - mean[1]) / mean[1],
                                                                 100 * (mean[0] - mean[2]) / mean[0], mean[3], mean[4]))


if __name__ == '__main__':
    main()
