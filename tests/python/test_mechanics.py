"""The mechanics binding: load() on the relaxed trefoil pressed between plates
(one snap, back to its state when released) and pulled apart at two touching
strands (the work is the energy gained plus the energy the snaps dissipated),
against the knots command's JSON, files and messages, and in a thread pool;
dynamics() on the trefoil thrown through itself against `knots dynamics`."""
from concurrent.futures import ThreadPoolExecutor
import math
import os

import numpy as np
import pytest

import elastic_knots as ek
from conftest import without_times

EI = 2000.0 * math.pi * 0.2 ** 4 / 4.0  # bending stiffness of the default material
RADIUS = 0.2                             # its wire radius: the plates' reach


@pytest.fixture(scope="module")
def state():
    """The relaxed trefoil: 3_1 embedded from its braid with 96 vertices, then relaxed."""
    r = ek.relax(ek.embed("3_1", vertices=96).points)
    assert r.status == "converged-stable"
    return r.points


@pytest.fixture(scope="module")
def pressed(state):
    return ek.load(state, "plates", 0.4)


@pytest.fixture(scope="module")
def pulled(state):
    return ek.load(state, "pull", 30.0, vertices=(0, 48), go_on=True)


def trapezoid_work(path, sign):
    """∫ ∂E/∂μ dμ over the path's steps, a snap doing no work; ∂E/∂μ = sign · reaction."""
    steps = [k for k in range(1, len(path.parameter)) if path.event[k] != "snap"]
    return sign * sum(0.5 * (path.reaction[k - 1] + path.reaction[k]) * (path.parameter[k] - path.parameter[k - 1])
                      for k in steps)


def check_path(r, n, sign):
    """The path's arrays: one entry per point, every point a stable equilibrium of the trefoil;
    ∂E/∂μ = sign · reaction."""
    p = r.path
    m = r.points
    for name in ("parameter", "displacement", "reaction", "stiffness", "energy", "load_energy", "gradient_norm",
                 "index", "lowest_eigenvalue", "stable", "corrector_iterations"):
        assert p[name].shape == (m,), name
    assert p.points.shape == (m, n, 3) and len(p.event) == m
    assert np.all(p.index == 0) and np.all(p.stable)
    assert p.parameter[0] == r["from"] and p.parameter[-1] == r.end_parameter
    assert p.energy[0] == r.start_energy and p.energy[-1] == r.end_energy
    assert [k for k in range(m) if p.event[k] == "snap"] == [s.point for s in r.snaps]
    assert set(p.event) <= {"regular", "snap"}
    assert r.alexander_preserved and ek.alexander(p.points[-1]) == [1, -1, 1]
    for s in r.snaps:
        assert np.array_equal(s.loaded, p.points[s.point])
        assert s.parameter == p.parameter[s.point - 1] and s.reaction == p.reaction[s.point - 1]
        assert s.loaded_energy == p.energy[s.point]
        # released at one control, the snap's: the branch's last state moved from its control to the snap's
        # changes the load's energy by ∂E/∂μ·Δμ (plus ½kΔμ² for the pull's spring, exact for its quadratic)
        step = p.parameter[s.point] - p.parameter[s.point - 1]
        moved = sign * p.reaction[s.point - 1] * step + (0.5 * r.pull_stiffness * step ** 2 if r.load == "pull" else 0.0)
        assert s.energy_drop > 0.0
        assert s.energy_drop == pytest.approx(p.energy[s.point - 1] - p.energy[s.point] + moved, rel=1e-7)
        assert s.released_status == "converged-stable"
        assert ek.alexander(s.released) == [1, -1, 1]
    assert r.dissipated == pytest.approx(sum(s.energy_drop for s in r.snaps), rel=1e-12)


def test_pressed_trefoil_snaps_once_and_springs_back(state, pressed):
    r = pressed
    check_path(r, 96, -1.0)
    assert r.load == "plates" and r.parameter == "gap" and r.to == 0.4
    assert r.vertices is None and r.pull_stiffness is None
    assert np.linalg.norm(r.normal) == pytest.approx(1.0, rel=1e-12)
    assert r.status == "stopped" and len(r.snaps) == 1  # it snaps before the gap reaches 0.4
    s = r.snaps[0]
    assert s.point == r.points - 1 and r.path.event[-1] == "snap"
    assert s.parameter > 0.4 and s.reaction > 0.0 and s.energy_drop > 0.0
    assert s.jump > 0.1 * np.mean(np.linalg.norm(np.roll(state, -1, axis=0) - state, axis=1))
    # released, it relaxes back to the start's state
    assert s.released_energy == pytest.approx(r.start_energy, rel=1e-6)
    # the plates start at the relaxed state's extent along the normal plus one wire radius on each side,
    # close monotonically, push ever harder (negative secant stiffness), and keep every vertex between them
    p = r.path
    heights = p.points @ np.asarray(r.normal)  # (points, n): the plates are centred on the start's extent
    middle = 0.5 * (heights[0].max() + heights[0].min())
    depth = np.abs(heights - middle)
    assert r["from"] == pytest.approx(2.0 * (depth[0].max() + RADIUS), rel=1e-12)
    assert np.all(np.diff(p.parameter[:-1]) < 0.0)
    assert np.all(p.reaction[1:] > 0.0)
    assert np.all(p.stiffness[1:-1] < 0.0) and np.isnan(p.stiffness[0]) and np.isnan(p.stiffness[-1])
    assert np.all(depth.max(axis=1) < p.parameter / 2.0)
    # the work of the plates, ∂E/∂g = -reaction (measured: 132.45 against ΔE + dissipated = 131.29)
    assert r.work == pytest.approx(trapezoid_work(p, -1.0), rel=1e-12)
    assert r.work == pytest.approx(r.end_energy - r.start_energy + r.dissipated, rel=0.02)


def test_pulled_trefoil_reaches_the_target_and_the_work_is_the_energy_gained(state, pulled):
    r = pulled
    check_path(r, 96, 1.0)
    assert r.load == "pull" and r.parameter == "distance" and r.vertices == [0, 48] and r.normal is None
    assert r.status == "reached" and r.end_parameter == pytest.approx(30.0, abs=1e-12)
    ell = np.mean(np.linalg.norm(np.roll(state, -1, axis=0) - state, axis=1))
    assert r.pull_stiffness == pytest.approx(100.0 * EI / ell ** 3, rel=1e-12)
    p = r.path
    assert r["from"] == pytest.approx(np.linalg.norm(p.points[0][0] - p.points[0][48]), rel=1e-12)
    # the stiff spring: the measured distance follows the control; the device pulls
    assert np.allclose(p.displacement, p.parameter, rtol=1e-3, atol=0.0)
    # (at the first points the touching strands push back a little: measured -8.6e-6 against 0.073 at the end)
    assert p.reaction[-1] > 0.0 and p.reaction.min() > -1e-3 * p.reaction.max()
    assert np.allclose(p.displacement, np.linalg.norm(p.points[:, 0] - p.points[:, 48], axis=1), rtol=1e-12)
    # two touching strands slide apart in small snaps; each released state relaxes back to the start
    assert len(r.snaps) >= 1 and all(s.energy_drop > 0.0 for s in r.snaps)
    assert all(s.released_energy == pytest.approx(r.start_energy, rel=1e-6) for s in r.snaps)
    # the work: ∂E/∂D = reaction, and ΔE plus the dissipated energy (measured within 0.1%)
    assert r.work == pytest.approx(trapezoid_work(p, 1.0), rel=1e-12)
    gained = r.end_energy - r.start_energy
    assert gained > 0.0
    assert r.work == pytest.approx(gained + r.dissipated, rel=0.01)


def test_stopping_at_the_first_snap_is_the_start_of_going_on(state, pulled):
    r = ek.load(state, "pull", 30.0, vertices=(0, 48))
    assert r.status == "stopped" and len(r.snaps) == 1 and r.points == pulled.snaps[0].point + 1
    assert np.array_equal(r.path.points, pulled.path.points[:r.points])
    for key in ("point", "parameter", "reaction", "jump", "energy_drop", "released_energy"):
        assert r.snaps[0][key] == pulled.snaps[0][key], key


def json_of(result):
    """A load Result as the command's JSON: without its arrays and the path."""
    d = {k: v for k, v in result.to_dict().items() if k != "path"}
    d["snaps"] = [{k: v for k, v in s.items() if k not in ("loaded", "released")} for s in d["snaps"]]
    return d


def test_load_equals_the_cli(knots, tmp_path, state, pressed, dataset_path):
    src = str(tmp_path / "state.obj")
    ek.write_curve(src, state)
    out = tmp_path / "plates"
    cli = knots.json("load", src, "--plates", "--to", "0.4", "-o", out)
    expected = {k: v for k, v in cli.items() if k not in ("input", "output")}
    assert without_times(json_of(pressed)) == without_times(expected)
    assert list(json_of(pressed)) == list(expected)  # the command's key order
    assert np.array_equal(pressed.path.points[0], ek.read_curve(str(out / "start.obj")))
    assert np.array_equal(pressed.path.points[-1], ek.read_curve(str(out / "end.obj")))
    assert np.array_equal(pressed.snaps[0].loaded, ek.read_curve(str(out / "snap_0_loaded.obj")))
    assert np.array_equal(pressed.snaps[0].released, ek.read_curve(str(out / "snap_0_released.obj")))
    rows = np.genfromtxt(out / "path.csv", delimiter=",", names=True, dtype=None, encoding="utf-8")
    assert len(rows) == pressed.points
    for name in ("parameter", "displacement", "reaction", "stiffness", "energy", "load_energy", "gradient_norm",
                 "lowest_eigenvalue"):
        assert np.allclose(pressed.path[name], rows[name], rtol=1e-11, atol=1e-300, equal_nan=True), name
    for name in ("index", "corrector_iterations"):
        assert np.array_equal(pressed.path[name], rows[name]), name
    assert list(pressed.path.event) == list(rows["event"])
    # with options, and matched to a data set's equilibria
    r = ek.load(state, "plates", 0.4, from_=0.9, normal=[0.0, 0.0, 1.0], steps=20, max_points=50,
                rest_length=1.0, dataset=dataset_path)
    cli = knots.json("load", src, "--plates", "--to", "0.4", "--from", "0.9", "--normal", "0,0,1", "--steps", "20",
                     "--max-points", "50", "--rest-length", "1", "--dataset", dataset_path, "-o", tmp_path / "options")
    expected = {k: v for k, v in cli.items() if k not in ("input", "output")}
    assert without_times(json_of(r)) == without_times(expected)
    assert r["from"] == 0.9 and r.normal == [0.0, 0.0, 1.0] and len(r.snaps) == 1
    assert r.start_match.knot == "3_1"
    assert all(s.released_match.knot == "3_1" for s in r.snaps)


def test_a_path_without_a_point_is_a_result(state):
    """Plates starting at a gap that presses the relaxed state (0.7 < 0.80): the start does not
    converge, the path stalls there with no point, and the result says so (no crash)."""
    r = ek.load(state, "plates", 0.4, from_=0.7)
    assert r.points == 0 and len(r.path.parameter) == 0 and r.path.points.shape == (0, 96, 3)
    assert r.status == "stalled" and r.snaps == [] and r.work == 0.0 and r["from"] == 0.7
    assert r.end_energy is None and r.end_parameter is None and r.start_match is None


def test_bad_input_is_a_value_error_with_the_cli_message(knots, tmp_path, state):
    src = str(tmp_path / "state.obj")
    ek.write_curve(src, state)
    out = str(tmp_path / "never")
    cases = [(("pull", 30.0), {"vertices": (3, 3)}, ["--pull", "3,3", "--to", "30"]),
             (("pull", 30.0), {"vertices": (3, 500)}, ["--pull", "3,500", "--to", "30"]),
             (("pull", 30.0), {"vertices": (0, 48), "normal": (0, 0, 1)},
              ["--pull", "0,48", "--to", "30", "--normal", "0,0,1"]),
             (("pull", 30.0), {"rest_length": -1.0}, ["--pull", "0,48", "--to", "30", "--rest-length", "-1"]),
             (("plates", 0.3), {}, ["--plates", "--to", "0.3"]),  # thinner than the wire
             (("pull", -5.0), {"vertices": (0, 48)}, ["--pull", "0,48", "--to", "-5"]),  # a negative distance
             (("plates", 0.5), {"from_": 0.01}, ["--plates", "--to", "0.5", "--from", "0.01"]),
             (("plates", 0.5), {"normal": (0, 0, 0)}, ["--plates", "--to", "0.5", "--normal", "0,0,0"]),
             (("plates", 0.5), {"steps": 0}, ["--plates", "--to", "0.5", "--steps", "0"])]
    for args, kwargs, cli in cases:
        with pytest.raises(ValueError) as e:
            ek.load(state, *args, **kwargs)
        assert str(e.value) == knots.error("load", src, *cli, "-o", out), kwargs
    assert not os.path.exists(out)
    with pytest.raises(ValueError, match=r"^unknown load 'twist' \(expected pull, plates or force\)$"):
        ek.load(state, "twist", 1.0)
    with pytest.raises(ValueError, match="vertices apply to pull and force only"):
        ek.load(state, "plates", 0.5, vertices=(0, 48))
    with pytest.raises(ValueError, match=r"shape \(96, 2\)"):
        ek.load(state[:, :2], "plates", 0.5)
    with pytest.raises(TypeError):
        ek.load(state, "pull", 30.0, vertices=(0, 1, 2))
    with pytest.raises(TypeError):
        ek.load(state, "pull", 30.0, (0, 48))  # options are keyword-only


def test_load_in_a_thread_pool_equals_sequential_loads(state, pressed):
    jobs = [("plates", 0.4, {}), ("pull", 30.0, {"vertices": (0, 48)})]
    sequential = [pressed, ek.load(state, "pull", 30.0, vertices=(0, 48))]
    with ThreadPoolExecutor(max_workers=2) as pool:
        parallel = list(pool.map(lambda job: ek.load(state, job[0], job[1], **job[2]), jobs))
    for s, p in zip(sequential, parallel):
        assert without_times(json_of(s)) == without_times(json_of(p))
        assert np.array_equal(s.path.points, p.path.points)


def thrown_velocity(x):
    """Every vertex towards the centroid and spinning about z (the CLI test's throw)."""
    c = x.mean(axis=0)
    v = -0.5 * (x - c)
    v[:, 0] += -0.5 * (x[:, 1] - c[1])
    v[:, 1] += 0.5 * (x[:, 0] - c[0])
    return v


def test_dynamics_equals_the_cli(knots, tmp_path, state):
    """A trefoil thrown through itself with friction: the same run as `knots dynamics`
    (keys, values, the trajectory's columns and frames), its type kept."""
    src, vel = str(tmp_path / "state.obj"), str(tmp_path / "velocity.obj")
    ek.write_curve(src, state)
    v = thrown_velocity(state)
    ek.write_curve(vel, v)
    r = ek.dynamics(state, velocity=v, time_step=0.05, duration=2.0, friction=0.3, frame_every=5)
    out = tmp_path / "thrown"
    cli = knots.json("dynamics", src, "--velocity", vel, "--time-step", "0.05", "--duration", "2", "--friction",
                     "0.3", "--frame-every", "5", "-o", out)
    expected = {k: v for k, v in cli.items() if k not in ("input", "output")}
    mine = {k: v for k, v in r.to_dict().items() if k not in ("trajectory", "positions", "velocities")}
    assert without_times(mine) == without_times(expected)
    assert list(mine) == list(expected)  # the command's key order
    assert r.status == "duration" and r.steps == 40 and r.alexander_preserved
    t = r.trajectory
    assert t.frames.shape == (9, len(state), 3) and np.array_equal(t.frames[-1], r.positions)
    assert np.array_equal(r.positions, ek.read_curve(str(out / "end.obj")))
    rows = np.genfromtxt(out / "trajectory.csv", delimiter=",", names=True)
    for name in ("time", "kinetic", "elastic", "gravity", "total", "max_speed", "threedim"):
        assert np.allclose(t[name], rows[name], rtol=1e-11, atol=1e-300), name
    assert np.array_equal(t.contacts, rows["contacts"]) and np.array_equal(t.newton_iterations, rows["newton_iterations"])
    assert ek.alexander(r.positions) == ek.alexander(state)


def test_dynamics_bad_input_is_a_value_error_with_the_cli_message(knots, tmp_path, state):
    src = str(tmp_path / "state.obj")
    ek.write_curve(src, state)
    out = str(tmp_path / "never")
    cases = [({"time_step": 0.0}, ["--time-step", "0"]),
             ({"friction": -1.0}, ["--friction", "-1"]),
             ({"envelope": 0.1}, ["--envelope", "0.1"]),
             ({"rest_length": 1.0, "rest_from": state}, ["--rest-length", "1", "--rest-from", src])]
    for kwargs, cli in cases:
        with pytest.raises(ValueError) as e:
            ek.dynamics(state, **kwargs)
        assert str(e.value) == knots.error("dynamics", src, *cli, "-o", out), kwargs
    assert not os.path.exists(out)
    with pytest.raises(ValueError, match="the start velocities must be n finite rows"):
        ek.dynamics(state, velocity=np.zeros((5, 3)))
