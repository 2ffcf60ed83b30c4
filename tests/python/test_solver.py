"""The solver bindings: energy() on known answers, relax() against the knots
command (every option it maps), and its errors."""
import math

import numpy as np
import pytest

import elastic_knots as ek
from conftest import json_part, trefoil, without_times

EI = 2000.0 * math.pi * 0.2 ** 4 / 4.0  # bending stiffness of the default material


def covered_circle(n, turns, radius):
    """`turns` times around a circle of `radius`: vertex i at angle 2π·turns·i/n (gcd(turns, n) = 1)."""
    t = 2.0 * np.pi * turns * np.arange(n) / n
    return np.column_stack([radius * np.cos(t), radius * np.sin(t), np.zeros(n)])


def test_bending_energy_of_a_three_covered_circle():
    n, R = 301, 16.0
    P = covered_circle(n, 3, R)
    e = ek.energy(P)
    phi = 6.0 * np.pi / n                 # turning angle at every vertex
    edge = 2.0 * R * np.sin(phi / 2.0)    # rest length = the edges' own length
    discrete = n * EI / 2.0 * (2.0 * np.tan(phi / 2.0)) ** 2 / edge  # Σ EI/2 |κb|² / ℓ
    assert e.energy_bend == pytest.approx(discrete, rel=1e-12)
    # the continuum 3-covered circle: EI/2 ∫ κ² = EI/2 · 3·2πR / R² = 3π EI / R (rel. error ~ φ²/5)
    assert e.energy_bend == pytest.approx(3.0 * np.pi * EI / R, rel=2e-3)
    assert e.energy_stretch == 0.0 and e.energy_twist == 0.0
    assert e.model == "twist-free" and e.vertices == n
    assert e.contacts > 0  # the three passes cross in the plane


def test_energy_options_and_the_cli(knots, curve_file):
    P = trefoil()
    path = curve_file(P)
    for kwargs, args in [({}, []),
                         ({"link": 1.5, "radius": 0.3}, ["--link", "1.5", "--radius", "0.3"]),
                         ({"rest_length": 1.1, "young": 1000.0, "poisson": 0.4},
                          ["--rest-length", "1.1", "--young", "1000", "--poisson", "0.4"])]:
        r = ek.energy(P, **kwargs)
        cli = knots.json("energy", path, *args)
        del cli["file"]
        assert r.to_dict() == cli, kwargs
    fixed = ek.energy(P, link=1.5)
    assert fixed.model == "fixed-link"
    assert fixed.link == pytest.approx(1.5, abs=1e-12)
    assert fixed.twist == pytest.approx(1.5 - fixed.writhe, abs=1e-12)
    # stretching with rest length L: Σ EA/2 (|e|/L - 1)² L
    edges = np.linalg.norm(np.roll(P, -1, axis=0) - P, axis=1)
    EA = 2000.0 * np.pi * 0.2 ** 2
    expected = np.sum(EA / 2.0 * (edges / 1.1 - 1.0) ** 2 * 1.1)
    assert ek.energy(P, rest_length=1.1).energy_stretch == pytest.approx(expected, rel=1e-12)


def compare_relax(knots, tmp_path, P, kwargs, args):
    """ek.relax(P, **kwargs) against knots relax FILE ARGS: equal JSON (up to times) and equal curves."""
    src = str(tmp_path / "in.obj")
    out = str(tmp_path / "out.obj")
    ek.write_curve(src, P)
    cli = knots.json("relax", src, "-o", out, *args)
    r = ek.relax(P, **kwargs)
    expected = {k: v for k, v in cli.items() if k not in ("file", "output", "trace")}
    got = {k: v for k, v in json_part(r).items() if k not in ("output", "trace")}
    assert without_times(got) == without_times(expected)
    assert np.array_equal(r.points, ek.read_curve(out))
    return r


def test_relax_equals_the_cli(knots, tmp_path):
    r = compare_relax(knots, tmp_path, trefoil(), {}, [])
    assert r.converged and r.stable and r.status == "converged-stable"
    assert r.alexander_preserved and r.alexander == [1, -1, 1]
    assert r.method == "default" and r.coarse_vertices == [60]
    assert r.points.shape == (120, 3)
    assert r.report.iterations == r.iterations
    assert r.energy == pytest.approx(r.energy_stretch + r.energy_bend + r.energy_twist + r.energy_contact
                                     + r.energy_slab, rel=1e-12)


def test_relax_options_equal_the_cli(knots, tmp_path):
    P = trefoil(100)
    trace = str(tmp_path / "trace.csv")
    r = compare_relax(knots, tmp_path, P,
                      {"method": "hybrid", "continuation": [1e-3], "factorization": "cholmod", "eigen": True,
                       "max_iter": 3000, "trace": trace},
                      ["--method", "hybrid", "--continuation", "1e-3", "--factorization", "cholmod", "--eigen",
                       "--max-iter", "3000"])
    assert len(r.phases) == 2 and r.phases[1] == "final" and len(r.continuation_reports) == 1
    assert r.phases[0].split()[0] == "continuation" and float(r.phases[0].split()[1]) == 1e-3
    assert r.smallest_eigenvalue > 0.0
    assert r.trace == trace
    rows = np.genfromtxt(trace, delimiter=",", names=True, dtype=None, encoding="utf-8")
    assert len(rows) == r.total_iterations + len(r.phases)  # one row per iteration, and a final row per phase
    flat = P * np.array([1.0, 1.0, 0.05])  # |z| <= 0.5
    r = compare_relax(knots, tmp_path, flat, {"planar": 1.0, "release": True, "coarse_levels": 0},
                      ["--planar", "1", "--release", "--coarse-levels", "0"])
    assert r.phases == ["slab", "final"] and r.slab_energy.energy_slab >= 0.0
    held = ek.relax(flat, planar=1.0, coarse_levels=0)
    assert held.phases == ["slab"] and np.max(np.abs(held.points[:, 2])) < 1.0  # the slab |z| < H holds
    r = compare_relax(knots, tmp_path, P, {"link": 0.0, "tol": 1e-7, "radius": 0.25, "young": 1500.0},
                      ["--link", "0", "--tol", "1e-7", "--radius", "0.25", "--young", "1500"])
    assert r.model == "fixed-link" and r.link == pytest.approx(0.0, abs=1e-9)


def test_relax_bad_input_is_a_value_error_with_the_cli_message(knots, curve_file):
    P = trefoil(60)
    path = curve_file(P)
    cases = [({"release": True}, ["--release"]),
             ({"method": "fast"}, ["--method", "fast"]),
             ({"factorization": "lu"}, ["--factorization", "lu"]),
             ({"continuation": [2.0]}, ["--continuation", "2"]),
             ({"radius": -1.0}, ["--radius", "-1"]),
             ({"coarse_levels": 9}, ["--coarse-levels", "9"])]
    for kwargs, args in cases:
        with pytest.raises(ValueError) as e:
            ek.relax(P, **kwargs)
        assert str(e.value) == knots.error("relax", path, *args), kwargs
    with pytest.raises(ValueError, match=r"shape \(60, 2\)"):
        ek.relax(P[:, :2])
    with pytest.raises(TypeError):
        ek.relax(P, 1.0)  # options are keyword-only


def test_topology_error_is_a_runtime_error():
    assert issubclass(ek.TopologyError, RuntimeError)
