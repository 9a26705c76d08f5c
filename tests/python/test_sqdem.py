"""The Python module against the CLI and its own contract (docs/python.md): the same bits as
`sqdem run` (one process, and two ranks under mpirun), zero-copy read-only views that see the
next step, setters that take effect, validation errors with their keys, callbacks that stop a
run, the single-contact driver's curves as the CLI's CSV, the detector and the contact ellipses.
Run by CTest with PYTHONPATH=build/python and SQDEM=<the sqdem executable>."""

import copy
import csv
import json
import os
import pathlib
import subprocess
import sys

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


@pytest.fixture(scope="module")
def cli_particles(tmp_path_factory):
    """small_bed's particle file from `sqdem run` (two threads)."""
    out = tmp_path_factory.mktemp("cli")
    subprocess.run([SQDEM, "run", str(SMALL_BED), "--out", str(out), "--threads", "2"], check=True,
                   stdout=subprocess.DEVNULL)
    return (out / "small_bed_final_particles.csv").read_bytes()


def test_a_scene_run_from_python_gives_the_clis_particle_file(tmp_path, cli_particles):
    sim = sqdem.Simulation(sqdem.Scene.load(str(SMALL_BED)), threads=1, out=str(tmp_path / "py"))
    assert sim.run() == "completed"
    assert (tmp_path / "py" / "small_bed_final_particles.csv").read_bytes() == cli_particles
    # Without files, paused at a stage's end, stepped, stopped by a callback and run on: the same state.
    quiet = sqdem.Simulation(sqdem.Scene.load(str(SMALL_BED)), threads=2)
    assert quiet.run(stage="pour") == "paused" and quiet.stage == "press"
    assert quiet.step(123) == "paused"
    stop_at = quiet.step_count + 1000
    quiet.every(1, lambda s: s.stop() if s.step_count == stop_at else None)
    assert quiet.run() == "stopped" and quiet.step_count == stop_at
    assert quiet.run() == "completed" and quiet.finished
    quiet.write_particles(str(tmp_path / "quiet.csv"))
    assert (tmp_path / "quiet.csv").read_bytes() == cli_particles
    # Stopped at the last step of a stage: the stage ends there, the run stops after it with a
    # checkpoint, and a simulation resumed from it ends alike.
    stopped = sqdem.Simulation(sqdem.Scene.load(str(SMALL_BED)), threads=2, out=str(tmp_path / "stopped"))
    last = stopped.stage_steps[0]
    stopped.every(1, lambda s: s.stop() if s.step_count == last else None)
    assert stopped.run() == "stopped" and stopped.step_count == last and stopped.stage == "press"
    resumed = sqdem.Simulation(sqdem.Scene.load(str(SMALL_BED)), threads=2, out=str(tmp_path / "stopped"),
                               resume=str(tmp_path / "stopped" / "small_bed_latest.checkpoint"))
    assert resumed.step_count == last and resumed.stage == "press" and resumed.run() == "completed"
    assert (tmp_path / "stopped" / f"small_bed_from_step{last}_final_particles.csv").read_bytes() == cli_particles


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


def test_setters_take_effect_and_views_are_read_only():
    sim = sqdem.Simulation(sqdem.Scene.from_dict(FREE, name="free"))
    p = sim.particles
    with pytest.raises(ValueError, match="read-only"):
        p.position[0, 2] = 4.0e-3
    position, velocity = p.position.copy(), p.velocity.copy()
    position[0, 2] = 4.0e-3
    velocity[0] = [0.5, -0.25, 0.125]
    p.set_position(position)
    p.set_velocity(velocity)
    p.set_angular_velocity(np.array([[0.0, 0.0, 10.0]]))
    sim.step(10)
    dt = sim.time_step
    x = sim.particles.position[0]
    expected = np.array([5.0e-3, 5.0e-3, 4.0e-3])
    for _ in range(10):
        expected = expected + dt * np.array([0.5, -0.25, 0.125])
    assert np.array_equal(x, expected)
    assert np.allclose(sim.particles.angular_velocity[0], [0, 0, 10.0], rtol=0, atol=1e-12)
    # A quaternion is normalised, the angular velocity kept (the momentum follows it).
    p.set_orientation(np.array([[0.0, 0.0, 3.0, 4.0]]))
    assert np.array_equal(sim.particles.orientation[0], [0.0, 0.0, 0.6, 0.8])
    assert np.allclose(sim.particles.angular_velocity[0], [0, 0, 10.0], rtol=0, atol=1e-12)
    for bad, match in ((np.zeros((1, 4)), "orientation: row 0 is the zero quaternion"),
                       (np.array([[0.0, np.nan, 0.0, 1.0]]), "orientation: row 0 is not finite"),
                       (np.zeros((2, 4)), "expected 1 rows of 4 values")):
        with pytest.raises(ValueError, match=match):
            p.set_orientation(bad)
    assert np.array_equal(sim.particles.orientation[0], [0.0, 0.0, 0.6, 0.8])  # a refused set changes nothing


def test_speed_given_from_python_is_not_taken_for_an_instability():
    # 50 m/s given to a 1 mm glass sphere at rest without gravity: 500 x the health checks' start
    # budget (E_kin(0) + m (1 m/s)^2 / 2); the energy given joins the budget.
    sim = sqdem.Simulation(sqdem.Scene.from_dict(FREE, name="free"))
    sim.step(1)  # the run has started: its health checks hold their budget
    sim.particles.set_velocity(np.array([[50.0, 0.0, 0.0]]))
    assert sim.step(30) == "paused"


def test_an_overlap_made_by_moving_a_particle_is_not_taken_for_an_instability():
    # Two stiff glass spheres (E = 70 GPa, 1 mm) at rest without gravity; one moved into a 0.05 mm
    # overlap stores ~1e-2 J, ~100 x the health checks' start budget; the next steps turn it into
    # kinetic energy as the spheres push apart.
    stiff = copy.deepcopy(FREE)
    stiff["time_step"] = 2.0e-7
    stiff["materials"]["glass"]["youngs_modulus"] = 7.0e10
    stiff["particles"] = [{"shape": "ball", "material": "glass", "centre": [3.0e-3, 5.0e-3, 5.0e-3]},
                          {"shape": "ball", "material": "glass", "centre": [5.2e-3, 5.0e-3, 5.0e-3]}]
    sim = sqdem.Simulation(sqdem.Scene.from_dict(stiff, name="stiff"))
    sim.step(1)
    position = sim.particles.position.copy()
    position[sim.particles.id == 1, 0] -= 2.5e-4
    sim.particles.set_position(position)
    assert sim.step(200) == "paused"
    assert sim.measures()["kinetic_energy"] > 1e-3


def test_a_particle_moved_onto_another_is_solved_at_the_next_step():
    # Two ellipsoids at rest without gravity, tip to tip 0.1 mm apart: found separated, their pair
    # is not solved again while the particles cannot have closed the gap (they do not move). One
    # moved by 0.15 mm (less than half the skin: the neighbour list stays) now overlaps by 0.05 mm.
    two = copy.deepcopy(FREE)
    two["skin"] = 4.0e-4
    two["shapes"] = {"egg": {"semi_axes": [1.2e-3, 1.0e-3, 1.0e-3]}}
    two["particles"] = [{"shape": "egg", "material": "glass", "centre": [3.0e-3, 5.0e-3, 5.0e-3]},
                        {"shape": "egg", "material": "glass", "centre": [5.5e-3, 5.0e-3, 5.0e-3]}]
    sim = sqdem.Simulation(sqdem.Scene.from_dict(two, name="two"))
    sim.step(5)
    assert not sim.contacts.acting.any()
    position = sim.particles.position.copy()
    position[sim.particles.id == 1, 0] -= 1.5e-4
    sim.particles.set_position(position)
    sim.step(1)
    c = sim.contacts
    assert c.acting.sum() == 1
    assert c.overlap[c.acting.astype(bool)][0] == pytest.approx(5.0e-5, rel=1e-3)
    assert np.all(sim.particles.force[:, 0] != 0.0)


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


def test_stop_asks_only_its_own_simulation():
    a = sqdem.Simulation(sqdem.Scene.load(str(SMALL_BED)))
    b = sqdem.Simulation(sqdem.Scene.from_dict(FREE))
    a.every(10, lambda s: b.stop())  # b is not running: nothing to stop
    assert a.step(50) == "paused" and a.step_count == 50
    b.stop()  # outside a run: nothing
    assert b.step(3) == "paused" and b.step_count == 3


def test_callbacks_see_the_step_a_stop_criterion_ends_a_stage_at_and_may_stop_there(tmp_path):
    # small_bed's pour ended by its kinetic energy instead of its duration (checked every 100 steps).
    text = SMALL_BED.read_text().replace("    duration: 0.06\n", "    duration: 0.06\n    stop: {kinetic_energy_ratio: 5, after: 0.01}\n")
    scene = sqdem.Scene.from_text(text, name="small_bed_stopping", directory=str(SMALL_BED.parent))
    whole = sqdem.Simulation(scene)
    seen = []
    whole.every(10, lambda s: seen.append((s.step_count, s.stage)))
    assert whole.run(stage="pour") == "paused"
    end = whole.step_count
    assert end < whole.stage_steps[0] and end % 100 == 0  # the criterion ended it
    assert seen[-1] == (end, "pour")
    with pytest.raises(ValueError, match="stage 'pour' has ended already"):
        whole.run(stage="pour")
    assert whole.run() == "completed"
    whole.write_particles(str(tmp_path / "whole.csv"))
    # Stopped at that step: the stage ends there, the run stops after it, and runs on alike.
    stopped = sqdem.Simulation(scene)
    stopped.every(10, lambda s: s.stop() if s.step_count == end else None)
    assert stopped.run() == "stopped" and stopped.step_count == end and stopped.stage == "press"
    assert stopped.run() == "completed"
    stopped.write_particles(str(tmp_path / "stopped.csv"))
    assert (tmp_path / "stopped.csv").read_bytes() == (tmp_path / "whole.csv").read_bytes()


def test_a_scene_from_text_names_its_files_as_given(tmp_path):
    sim = sqdem.Simulation(sqdem.Scene.from_dict(FREE, name="free_mu0.1"), out=str(tmp_path))
    assert sim.run() == "completed"
    assert (tmp_path / "free_mu0.1_final_particles.csv").exists()


def test_bad_arguments_raise_clear_errors():
    free = sqdem.Scene.from_dict(FREE)
    with pytest.raises(ValueError, match=r"threads: 5000 is not a count in \[0, 1024\]"):
        sqdem.Simulation(free, threads=5000)
    with pytest.raises(ValueError, match="'avx512': expected a SIMD path this CPU runs: scalar"):
        sqdem.Simulation(free, simd="avx512")
    with pytest.raises(ValueError, match=r"walls\[0\] is not a plate"):
        sqdem.Simulation(free).plate(0)
    bed = sqdem.Simulation(sqdem.Scene.load(str(SMALL_BED)))
    with pytest.raises(ValueError, match=r"walls\[0\] is not a plate"):  # the floor
        bed.plate(0)
    assert bed.plate(1)["gap"] == pytest.approx(12.0e-3)


def test_contact_ellipses_on_walls():
    # A sphere (r = 1 mm) on the barrel of a roller (R = 1 mm, axis y): relative curvatures 1/r
    # along the axis and 1/r + 1/R around it, so the ellipse's major axis lies along the axis. A
    # sphere on the roller's flat end: a circle. An ellipsoid (1.2, 1.0, 0.8) mm standing on the
    # floor: curvatures c/a^2 along x and c/b^2 along y at its lowest point, the major axis along x.
    scene = copy.deepcopy(FREE)
    scene["shapes"]["egg"] = {"semi_axes": [1.2e-3, 1.0e-3, 0.8e-3]}
    scene["walls"] = [{"point": [0, 0, 0], "normal": [0, 0, 1], "material": "glass"},
                      {"point": [5.0e-3, 5.0e-3, 5.0e-3], "axis": [0, 1, 0], "radius": 1.0e-3, "length": 4.0e-3,
                       "ends": "flat", "material": "glass"}]
    scene["particles"] = [{"shape": "ball", "material": "glass", "centre": [5.0e-3, 5.0e-3, 6.98e-3], "allow_overlap": True},
                          {"shape": "ball", "material": "glass", "centre": [5.0e-3, 7.98e-3, 5.0e-3], "allow_overlap": True},
                          {"shape": "egg", "material": "glass", "centre": [2.0e-3, 2.0e-3, 0.78e-3], "allow_overlap": True}]
    sim = sqdem.Simulation(sqdem.Scene.from_dict(scene))
    sim.step(1)
    c = sim.contacts
    semi_axes, axis = c.ellipses()
    acting = c.acting.astype(bool)
    assert acting.sum() == 3
    on = {}
    for k in np.flatnonzero(acting):
        on[(int(c.id_a[k]), int(c.id_b[k]) & ~sqdem.wall_flag)] = k
    barrel, end, floor = on[(0, 1)], on[(1, 1)], on[(2, 0)]
    for k in (barrel, end, floor):
        assert np.pi * semi_axes[k, 0] * semi_axes[k, 1] == pytest.approx(c.area[k], rel=1e-12)
    assert semi_axes[barrel, 0] > 1.2 * semi_axes[barrel, 1] and abs(axis[barrel, 1]) == pytest.approx(1.0, abs=1e-9)
    assert semi_axes[end, 0] == pytest.approx(semi_axes[end, 1], rel=1e-9)
    assert semi_axes[floor, 0] > semi_axes[floor, 1] and abs(axis[floor, 0]) == pytest.approx(1.0, abs=1e-9)


def test_contact_ellipses():
    # Two equal ellipsoids (a, b, c) = (1.2, 1.0, 0.8) mm tip to tip along x: at the tips both
    # surfaces' principal curvatures are a/b^2 (along y) and a/c^2 (along z), so the contact
    # ellipse's major axis is along y (the smaller relative curvature) and its aspect that of the
    # Hertz ellipse of those radii (004 Eq. 13), which the geometry probe gives as e2_exact.
    two = copy.deepcopy(FREE)
    two["shapes"] = {"egg": {"semi_axes": [1.2e-3, 1.0e-3, 0.8e-3]}}
    two["particles"] = [{"shape": "egg", "material": "glass", "centre": [3.0e-3, 5.0e-3, 5.0e-3], "allow_overlap": True},
                        {"shape": "egg", "material": "glass", "centre": [5.38e-3, 5.0e-3, 5.0e-3], "allow_overlap": True}]
    sim = sqdem.Simulation(sqdem.Scene.from_dict(two))
    sim.step(1)
    c = sim.contacts
    acting = c.acting.astype(bool)
    assert acting.sum() == 1
    semi_axes, axis = c.ellipses()
    a, b = semi_axes[acting][0]
    assert a >= b > 0
    assert np.pi * a * b == pytest.approx(c.area[acting][0], rel=1e-12)
    assert abs(axis[acting][0][1]) == pytest.approx(1.0, abs=1e-9)
    p = sim.particles.sorted_by_id()
    g = sqdem.geometry([1.2e-3, 1.0e-3, 0.8e-3], [2, 2], p["position"][0], p["orientation"][0],
                       [1.2e-3, 1.0e-3, 0.8e-3], [2, 2], p["position"][1], p["orientation"][1])
    assert (b / a) ** 2 == pytest.approx(1.0 - g["e2_exact"], rel=1e-6)


def test_the_probes_take_numpy_values_and_name_bad_ones():
    description = json.loads((ROOT / "examples" / "jkr_elliptic.json").read_text())
    plain = sqdem.contact(description)

    def numpied(value):
        if isinstance(value, dict):
            return {k: numpied(v) for k, v in value.items()}
        if isinstance(value, list):
            return np.array(value) if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value) \
                else [numpied(v) for v in value]
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            return value
        return np.int64(value) if isinstance(value, int) else np.float64(value)

    same = sqdem.contact(numpied(description))
    for mine, theirs in zip(same["curves"], plain["curves"]):
        assert np.array_equal(mine["normal_force"], theirs["normal_force"])
    bad = copy.deepcopy(description)
    first = next(k for k, v in bad["curves"][0]["law"].items() if isinstance(v, float))
    bad["curves"][0]["law"][first] = float("nan")
    with pytest.raises(sqdem.InputError, match=first):
        sqdem.contact(bad)
    with pytest.raises(TypeError, match="cannot be given"):
        sqdem.contact({"name": object()})


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
    # Apart beyond the cut-off: no normal, points or curvatures to give.
    apart = sqdem.geometry([1e-3, 1e-3, 1e-3], [2, 2], [0, 0, 0], [0, 0, 0, 1],
                           [1e-3, 1e-3, 1e-3], [2, 2], [3e-3, 0, 0], [0, 0, 0, 1])
    assert apart["status"].startswith("separated") and "normal" not in apart and "curvatures_a" not in apart
    with pytest.raises(sqdem.InputError, match=r"particles\[1\].*'a'"):
        sqdem.geometry([1e-3, 1e-3, 1e-3], [2, 2], [0, 0, 0], [0, 0, 0, 1],
                       [-1e-3, 1e-3, 1e-3], [2, 2], [3e-3, 0, 0], [0, 0, 0, 1])
    with pytest.raises(sqdem.InputError, match="quaternion"):
        sqdem.geometry([1e-3, 1e-3, 1e-3], [2, 2], [0, 0, 0], [0, 0, 0, 0],
                       [1e-3, 1e-3, 1e-3], [2, 2], [3e-3, 0, 0], [0, 0, 0, 1])


def test_mpirun_runs_a_python_script_as_the_ranks_of_one_run(tmp_path, cli_particles):
    script = tmp_path / "run.py"
    # Then a setter given a NaN on rank 1 only is refused on both ranks (none waits for the other).
    script.write_text("import sys\nimport numpy as np\nimport sqdem\n"
                      "sim = sqdem.Simulation(sqdem.Scene.load(sys.argv[1]), threads=1, out=sys.argv[2])\n"
                      "assert sim.ranks == 2 and sim.run() == 'completed'\n"
                      "v = sim.particles.velocity.copy()\n"
                      "if sim.rank == 1:\n    v[0, 0] = np.nan\n"
                      "try:\n    sim.particles.set_velocity(v)\nexcept ValueError as e:\n"
                      "    open(sys.argv[2] + f'/refused_{sim.rank}', 'w').write(str(e))\n")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    subprocess.run(["mpirun", "-np", "2", "--oversubscribe", sys.executable, str(script), str(SMALL_BED),
                    str(tmp_path / "ranks")], check=True, env=env, stdout=subprocess.DEVNULL, timeout=600)
    for rank in (0, 1):
        assert (tmp_path / "ranks" / f"refused_{rank}").read_text() == "velocity: row 0 is not finite"
    assert (tmp_path / "ranks" / "small_bed_final_particles.csv").read_bytes() == cli_particles
