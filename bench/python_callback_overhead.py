"""The cost of Python callbacks (docs/python.md): small_bed's first 4,000 steps (120 ellipsoids
pouring, one thread) run plain and with a callback every step that does nothing, that reduces
two particle views with NumPy, or that asks for the packing measures; the median of REPS
interleaved runs.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_callback_overhead.py [REPS]
"""

import pathlib
import statistics
import sys
import time

import sqdem

ROOT = pathlib.Path(__file__).resolve().parents[1]
STEPS = 4000


def timed(callback):
    sim = sqdem.Simulation(sqdem.Scene.load(str(ROOT / "tests" / "scenes" / "small_bed.yaml")), threads=1)
    sim.step(1)  # the set-up and first forces, not timed
    if callback is not None:
        sim.every(1, callback)
    start = time.perf_counter()
    sim.step(STEPS)
    return (time.perf_counter() - start) / STEPS


def viewing(sim):
    p = sim.particles
    p.position.mean(axis=0)
    p.velocity.max()


def measuring(sim):
    sim.measures()


def main():
    reps = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    cases = {"plain": None, "callback doing nothing": lambda sim: None, "callback reading two views": viewing,
             "callback calling measures()": measuring}
    seconds = {name: [] for name in cases}
    for _ in range(reps):
        for name, callback in cases.items():
            seconds[name].append(timed(callback))
    plain = statistics.median(seconds["plain"])
    print(f"small_bed, {STEPS} steps, 1 thread, median of {reps}")
    for name, values in seconds.items():
        t = statistics.median(values)
        print(f"{name:40s} {1e6 * t:8.2f} us/step   +{1e6 * (t - plain):7.2f} us/step ({100 * (t / plain - 1):+.1f} %)")


if __name__ == "__main__":
    main()
