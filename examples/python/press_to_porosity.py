"""A lid presses a poured bed; a callback logs the plate's pressure and porosity every 50
steps and stops the press when the porosity reaches a target.

Writes press_to_porosity.csv and press_to_porosity.png into OUT (default out/python).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/press_to_porosity.py [--porosity P] [--out DIR]
"""

import argparse
import csv
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import sqdem

# 120 glass ellipsoids poured into a box periodic in x and y (tests/scenes/small_bed.yaml's), then
# a lid (walls[1]) moves down at 0.4 m/s until the porosity under it reaches the target.
BED = {
    "seed": 7,
    "domain": {"lo": [0, 0, 0], "hi": [6.0e-3, 6.0e-3, 12.0e-3], "periodic": ["x", "y"]},
    "gravity": [0, 0, -9.81],
    "materials": {"glass": {"youngs_modulus": 1.0e7, "poisson_ratio": 0.3, "density": 2500, "friction": 0.3,
                            "restitution": 0.5}},
    "shapes": {"bead": {"volume_radius": [0.4e-3, 0.5e-3], "aspect_b": [0.7, 1.0], "aspect_c": [0.6, 1.0]}},
    "interactions": [{"materials": ["glass", "glass"]}],
    "walls": [{"point": [0, 0, 0], "normal": [0, 0, 1], "material": "glass"},
              {"point": [0, 0, 12.0e-3], "normal": [0, 0, -1], "material": "glass"}],
    "insert": [{"count": 120, "shape": "bead", "material": "glass",
                "region": {"lo": [0, 0, 0.6e-3], "hi": [6.0e-3, 6.0e-3, 11.0e-3]}}],
    "stages": [{"name": "pour", "duration": 0.06},
               {"name": "press", "duration": 0.03, "move_wall": {"wall": 1, "velocity": [0, 0, -0.4]}}],
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--porosity", type=float, default=0.40)
    parser.add_argument("--out", default="out/python")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    sim = sqdem.Simulation(sqdem.Scene.from_dict(BED, name="press"))
    sim.run(stage="pour")
    log = []

    def watch(s):
        plate = s.plate(1)
        log.append((s.time, plate["gap"], plate["pressure"], plate["porosity"]))
        if plate["porosity"] <= args.porosity:
            s.stop()

    sim.every(50, watch)
    outcome = sim.run()
    t, gap, pressure, porosity = log[-1]
    print(f"{outcome} at t = {t:.5f} s: gap {gap * 1e3:.3f} mm, plate pressure {pressure:.1f} Pa, porosity {porosity:.4f}")
    with open(out / "press_to_porosity.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["time_s", "gap_m", "pressure_Pa", "porosity"])
        writer.writerows(log)
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot([r[3] for r in log], [r[2] for r in log], "o-")
    ax.axvline(args.porosity, ls="--", c="grey")
    ax.set_xlabel("porosity between plate and floor")
    ax.set_ylabel("plate pressure (Pa)")
    ax.invert_xaxis()
    fig.tight_layout()
    fig.savefig(out / "press_to_porosity.png", dpi=120)
    print(f"wrote {out / 'press_to_porosity.csv'} and {out / 'press_to_porosity.png'}")


if __name__ == "__main__":
    main()
