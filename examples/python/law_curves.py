"""The normal force against the overlap of one NMC ellipsoid pair under every normal law of the
registry the single-contact driver drives (docs/contact_laws.md), through the single-contact driver (sqdem.contact): the pair is
posed, the detector gives its curvatures, each law is loaded to 40 nm and unloaded.

Writes law_curves.png into OUT (default out/python).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/law_curves.py [--out DIR]
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import sqdem

# Two NMC ellipsoids (E = 140 GPa, nu = 0.3; semi-axes 6 / 4 / 4 um and 5 / 5 / 3.5 um) touching
# along x, B turned 30 degrees about z.
PAIR = {
    "particles": [
        {"centre": [0, 0, 0], "quaternion": [1, 0, 0, 0], "a": 6e-6, "b": 4e-6, "c": 4e-6, "n1": 2, "n2": 2},
        {"centre": [10.5e-6, 0, 0], "quaternion": [0.9659258262890683, 0, 0, 0.25881904510252074],
         "a": 5e-6, "b": 5e-6, "c": 3.5e-6, "n1": 2, "n2": 2},
    ]
}
LAWS = {
    "elliptic_hertz": {},
    "becker_kamlah": {"yield_strength": 2.0e9},
    "jamari": {"hardness": 6.0e9},
    "haervig_jkr": {"surface_energy": 0.5},
    "elliptic_jkr": {"surface_energy": 0.5},
    "nan_adhesive": {"surface_energy": 0.5, "yield_pressure": 3.0e9},
}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="out/python")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    description = {
        "name": "law_curves",
        "material": {"youngs_modulus": 140e9, "poisson_ratio": 0.3},
        "path": {"unit": "um", "points": [-0.005, 0.04, -0.005], "steps": 200},
        "curves": [{"label": name, "geometry": PAIR, "law": {"type": name, **keys}} for name, keys in LAWS.items()],
    }
    result = sqdem.contact(description)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for curve in result["curves"]:
        ax.plot(curve["overlap"] * 1e9, curve["normal_force"] * 1e3, label=curve["label"])
        print(f"{curve['label']}: largest force {curve['normal_force'].max() * 1e3:.4f} mN, "
              f"radii {curve['radii'][0] * 1e6:.3f} / {curve['radii'][1] * 1e6:.3f} um")
    ax.set_xlabel("overlap (nm)")
    ax.set_ylabel("normal force (mN)")
    ax.axhline(0, c="grey", lw=0.5)
    ax.legend(fontsize=8)
    ax.set_title("one NMC ellipsoid pair, every normal law: load to 40 nm, unload")
    fig.tight_layout()
    fig.savefig(out / "law_curves.png", dpi=120)
    print(f"wrote {out / 'law_curves.png'}")


if __name__ == "__main__":
    main()
