"""The Python module against the CLI and its own contract (docs/python.md): the same bits as
`sqdem run`, zero-copy views that see the next step, writes that take effect, validation errors
with their keys, callbacks that stop a run, the single-contact driver's curves as the CLI's CSV.
Run by CTest with PYTHONPATH=build/python and SQDEM=<the sqdem executable>."""

import copy
import csv
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import sqdem

ROOT = pathlib.Path(__file__).resolve().parents[2]
SQDEM = os.environ["SQDEM"]
SMALL_BED = ROOT / "tests" / "scenes" / "small_bed.yaml"

# One glass sphere falling freely in an empty box (no gravity): x(t) = x0 + v t exactly per step.
FREE = {
    "domain": {"lo": [0, 0, 0], "hi": [0.01, 0.01, 0.01]},
    "time_step": 1.0e-6,
    "materials": {"glass": {"youngs_modulus": 1.0e7, "poisson_ratio": 0.3, "density": 2500}},
    "shapes": {"ball": {"semi_axes": [1.0e-3, 1.0e-3, 1.0e-3]}},
    "interactions": [{"materials": ["glass", "glass"]}],
    "particles": [{"shape": "ball", "material": "glass", "centre": [5.0e-3, 5.0e-3, 5.0e-3]}],
    "stages": [{"name": "fly", "duration": 1.0e-4}],
}


def test_a_scene_run_from_python_gives_the_clis_particle_file(tmp_path):
    subprocess.run([SQDEM, "run", str(SMALL_BED), "--out", str(tmp_path / "cli"), "--threads", "2"], check=True,
                   stdout=subprocess.DEVNULL)
    sim = sqdem.Simulation(sqdem.Scene.load(str(SMALL_BED)), threads=1, out=str(tmp_path / "py"))
    assert sim.run() == "completed"
    cli = (tmp_path / "cli" / "small_bed_final_particles.csv").read_bytes()
    assert (tmp_path / "py" / "small_bed_final_particles.csv").read_bytes() == cli
    # Without files, paused at a stage's end and stepped on: the same state.
    quiet = sqdem.Simulation(sqdem.Scene.load(str(SMALL_BED)), threads=2)
    assert quiet.run(stage="pour") == "paused" and quiet.stage == "press"
    assert quiet.step(123) == "paused"
    assert quiet.run() == "completed" and quiet.finished
    quiet.write_particles(str(tmp_path / "quiet.csv"))
    assert (tmp_path / "quiet.csv").read_bytes() == cli
    # Stopped at the last step of a stage, then run on: the stage ends without another step.
    stopped = sqdem.Simulation(sqdem.Scene.load(str(SMALL_BED)), threads=2)
    last = stopped.stage_steps[0]
    stopped.every(1, lambda s: s.stop() if s.step_count == last else None)
    assert stopped.run() == "stopped" and stopped.step_count == last and stopped.stage == "pour"
    assert stopped.run() == "completed"
    stopped.write_particles(str(tmp_path / "stopped.csv"))
    assert (tmp_path / "stopped.csv").read_bytes() == cli


def test_views_share_the_stores_memory_and_see_the_next_step():
    sim = sqdem.Simulation(sqdem.Scene.load(str(SMALL_BED)))
    sim.run(stage="pour")  # a settled bed: contacts
    p = sim.particles
    position = p.position
    assert position.shape == (120, 3) and not position.flags.owndata and position.base is not None
    assert np.shares_memory(position, sim.particles.position)
    before = position.copy()
    sim.step(1)
    after = sim.particles.position
    if np.shares_memory(position, after):  # no re-ordering this step: the old view sees the new values
        assert np.array_equal(position, after)
    assert not np.array_equal(before, after)
    assert not sim.particles.force.flags.writeable
    c = sim.contacts
    assert len(c) == c.overlap.shape[0] and c.acting.dtype == np.uint8
    acting = c.acting.astype(bool)
    assert acting.any() and np.all(c.overlap[acting] > 0)
    assert np.allclose(np.linalg.norm(c.normal[acting], axis=1), 1.0)
    m = sim.measures()
    assert 0 < m["solid_fraction"] < 1 and m["coordination"] > 0 and m["stress"].shape == (3, 3)
    ordered = sim.particles.sorted_by_id()
    assert np.array_equal(ordered["id"], np.arange(120))


def test_writes_to_positions_velocities_and_spins_take_effect():
    sim = sqdem.Simulation(sqdem.Scene.from_dict(FREE, name="free"))
    p = sim.particles
    p.velocity[0] = [0.5, -0.25, 0.125]
    p.position[0, 2] = 4.0e-3
    p.set_angular_velocity(np.array([[0.0, 0.0, 10.0]]))
    sim.step(10)
    dt = sim.time_step
    x = sim.particles.position[0]
    expected = np.array([5.0e-3, 5.0e-3, 4.0e-3])
    for _ in range(10):
        expected = expected + dt * np.array([0.5, -0.25, 0.125])
    assert np.array_equal(x, expected)
    assert np.allclose(sim.particles.angular_velocity[0], [0, 0, 10.0], rtol=0, atol=1e-12)


def test_validation_errors_raise_with_the_scene_key():
    bad = copy.deepcopy(FREE)
    bad["materials"]["glass"]["restitution"] = 1.5
    with pytest.raises(sqdem.SceneError, match=r"^free: 'materials.glass.restitution': must be in \(0, 1\]"):
        sqdem.Scene.from_dict(bad, name="free")
    bad = copy.deepcopy(FREE)
    bad["colour"] = "red"
    with pytest.raises(sqdem.SceneError, match=r"'colour': unknown key \(allowed: seed,"):
        sqdem.Scene.from_dict(bad)
    with pytest.raises(ValueError, match="no stage 'pour'"):
        sqdem.Simulation(sqdem.Scene.from_dict(FREE)).run(stage="pour")


def test_a_callback_stops_the_run():
    sim = sqdem.Simulation(sqdem.Scene.load(str(SMALL_BED)))
    seen = []

    def every_100(s):
        seen.append(s.step_count)
        if s.step_count == 300:
            s.stop()

    sim.every(100, every_100)
    assert sim.run() == "stopped"
    assert seen == [100, 200, 300] and sim.step_count == 300


def test_a_callbacks_exception_ends_the_run_and_reaches_python():
    sim = sqdem.Simulation(sqdem.Scene.load(str(SMALL_BED)))

    def fail(s):
        raise KeyError("from the callback")

    sim.every(7, fail)
    with pytest.raises(KeyError, match="from the callback"):
        sim.run()
    assert sim.step_count == 7


def test_a_laws_curve_is_the_cli_drivers_csv(tmp_path):
    description = json.loads((ROOT / "examples" / "jkr_elliptic.json").read_text())
    subprocess.run([SQDEM, "contact", str(ROOT / "examples" / "jkr_elliptic.json"), "--out", str(tmp_path)], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    result = sqdem.contact(description)
    assert len(result["curves"]) == len(description["curves"])
    for curve in result["curves"]:
        with open(tmp_path / f"{description.get('name', 'jkr_elliptic')}_{curve['label']}.csv") as f:
            rows = list(csv.DictReader(f))
        assert len(rows) == len(curve["overlap"]) == len(result["displacement"])
        ten = lambda x: format(x, ".10g")  # the CSV's precision (10 significant digits)
        for k, row in enumerate(rows):
            assert row["displacement"] == ten(result["displacement"][k])
            assert row["overlap"] == ten(curve["overlap"][k])
            assert row["normal_force"] == ten(curve["normal_force"][k])
            assert row["regime"] == curve["regime"][k]


def test_the_detector_on_one_pair():
    g = sqdem.geometry([1e-3, 1e-3, 1e-3], [2, 2], [0, 0, 0], [0, 0, 0, 1],
                       [1e-3, 1e-3, 1e-3], [2, 2], [1.9e-3, 0, 0], [0, 0, 0, 1])
    assert g["converged"]
    assert g["overlap"] == pytest.approx(1e-4, rel=1e-9)
    assert np.allclose(g["normal"], [1, 0, 0])
    assert g["curvatures_a"] == pytest.approx((1e3, 1e3), rel=1e-9)  # a sphere's: 1/R
