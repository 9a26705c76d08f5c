"""Solid fraction and coordination of a poured bed of ellipsoids against the friction coefficient.

Each friction value is one scene built as a dictionary (the scene file's keys) and run without
files; the measures are read from the simulation. Writes friction_sweep.csv and
friction_sweep.png into OUT (default out/python).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/friction_sweep.py [--particles N] [--out DIR]
"""

import argparse
import copy
import csv
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import sqdem

# Glass-like ellipsoids of R_vol 0.4-0.5 mm poured into a box periodic in x and y; the pour
# stops when the kinetic energy falls below 1e-4 of sum m g R_vol.
BED = {
    "seed": 11,
    "domain": {"lo": [0, 0, 0], "hi": [5.0e-3, 5.0e-3, 20.0e-3], "periodic": ["x", "y"]},
    "gravity": [0, 0, -9.81],
    "materials": {"glass": {"youngs_modulus": 1.0e7, "poisson_ratio": 0.3, "density": 2500, "restitution": 0.5}},
    "shapes": {"grain": {"volume_radius": [0.4e-3, 0.5e-3], "aspect_b": [0.6, 1.0], "aspect_c": [0.6, 1.0]}},
    "interactions": [{"materials": ["glass", "glass"]}],
    "walls": [{"point": [0, 0, 0], "normal": [0, 0, 1], "material": "glass"}],
    "insert": [{"count": 0, "shape": "grain", "material": "glass",
                "region": {"lo": [0, 0, 0.6e-3], "hi": [5.0e-3, 5.0e-3, 19.0e-3]}}],
    "stages": [{"name": "pour", "duration": 0.5, "stop": {"kinetic_energy_ratio": 1.0e-4, "after": 0.05}}],
}


def poured(friction, particles):
    scene = copy.deepcopy(BED)
    scene["materials"]["glass"]["friction"] = friction
    scene["insert"][0]["count"] = particles
    sim = sqdem.Simulation(sqdem.Scene.from_dict(scene, name=f"pour_mu{friction}"))
    sim.run()
    return sim.measures()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--particles", type=int, default=200)
    parser.add_argument("--out", default="out/python")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    frictions = [0.0, 0.1, 0.3, 0.6]
    rows = []
    for mu in frictions:
        m = poured(mu, args.particles)
        rows.append((mu, m["solid_fraction"], m["coordination"]))
        print(f"friction {mu:.2f}: solid fraction {m['solid_fraction']:.4f}, coordination {m['coordination']:.3f}")
    with open(out / "friction_sweep.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["friction", "solid_fraction", "coordination"])
        writer.writerows(rows)
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.5))
    a.plot(frictions, [r[1] for r in rows], "o-")
    a.set_xlabel("friction coefficient")
    a.set_ylabel("solid fraction (slab)")
    b.plot(frictions, [r[2] for r in rows], "o-")
    b.set_xlabel("friction coefficient")
    b.set_ylabel("mean coordination")
    fig.suptitle(f"poured bed of {args.particles} ellipsoids")
    fig.tight_layout()
    fig.savefig(out / "friction_sweep.png", dpi=120)
    print(f"wrote {out / 'friction_sweep.csv'} and {out / 'friction_sweep.png'}")


if __name__ == "__main__":
    main()
