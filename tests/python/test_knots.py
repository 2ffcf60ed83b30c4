"""The knots, embedding and lattice bindings: the knot table, Alexander
polynomials, writhe, invariants, embed and sample, against known answers and
the knots command's JSON on the same input."""
import os

import numpy as np
import pytest

import elastic_knots as ek
from conftest import trefoil


def test_knot_equals_knots_info(knots):
    k = ek.knot("8_19")
    assert k.to_dict() == knots.json("info", "8_19")
    assert k.name == "8_19" and k.crossing_number == 8
    # 8_19 is the torus knot T(3, 4): Δ = (t^12 - 1)(t - 1) / ((t^3 - 1)(t^4 - 1))
    assert k.alexander == [1, -1, 0, 1, 0, -1, 1] and k.determinant == 3
    assert k["braid_index"] == 3


def test_table_link_equals_knots_info(knots):
    b = ek.knot("borromean")
    assert b.to_dict() == knots.json("info", "L6a4")
    assert b.components == 3 and b.conway == [0, 0, 0, 0, 1] and b.milnor_triple == 1
    assert ek.knot("whitehead").linking_numbers == [[0, 0], [0, 0]]


def test_trefoil_alexander_polynomial():
    assert ek.knot("3_1").alexander == [1, -1, 1]
    assert ek.alexander("3_1") == [1, -1, 1]
    assert ek.alexander(trefoil()) == [1, -1, 1]
    assert ek.alexander("4_1") == [-1, 3, -1]
    assert ek.alexander("0_1") == [1]


def test_table_iteration_and_indexing():
    table = ek.knot_table()
    assert len(table) == 2978  # the unknot and the 2,977 prime knots up to 12 crossings
    first = [k.name for _, k in zip(range(4), table)]
    assert first == ["0_1", "3_1", "4_1", "5_1"]
    assert table[1].alexander == [1, -1, 1]
    assert table["4_1"].determinant == 5
    assert table[-1].crossing_number == 12
    small = ek.knot_table(max_crossings=5, include_unknot=False)
    assert small.names == ["3_1", "4_1", "5_1", "5_2"]
    assert [k.crossing_number for k in small] == [3, 4, 5, 5]
    assert os.path.samefile(table.path, ek.knot_table_path())


def test_unknown_knot_is_a_value_error_with_the_cli_message(knots):
    with pytest.raises(ValueError) as e:
        ek.knot("13_1")
    assert str(e.value) == knots.error("info", "13_1")


def test_writhe_known_answers():
    t = np.linspace(0.0, 2.0 * np.pi, 100, endpoint=False)
    circle = np.column_stack([np.cos(t), np.sin(t), np.zeros_like(t)])
    assert abs(ek.writhe(circle)) < 1e-12  # a planar curve has writhe 0
    P = trefoil()
    mirror = P * np.array([1.0, 1.0, -1.0])
    assert ek.writhe(P) == pytest.approx(-ek.writhe(mirror), abs=1e-12)
    assert abs(ek.writhe(P)) > 1.0  # the torus trefoil's writhe is about ±3.4


def test_invariants_equal_the_cli(knots, curve_file):
    P = trefoil()
    path = curve_file(P)
    r = ek.invariants(P)
    cli = knots.json("invariants", path)
    del cli["file"]
    assert r.to_dict() == cli
    assert r.alexander == [1, -1, 1] and r.determinant == 3 and r.vertices == len(P)


def test_embed_equals_the_cli(knots, tmp_path):
    out = str(tmp_path / "e.obj")
    cli = knots.json("embed", "5_2", "--from", "pd", "-n", "160", "--edge-length", "0.5", "-o", out)
    e = ek.embed("5_2", from_="pd", vertices=160, edge_length=0.5)
    expected = {k: v for k, v in cli.items() if k != "output"}
    assert {k: v for k, v in e.to_dict().items() if k != "points"} == expected
    assert e.points.shape == (160, 3)
    assert np.array_equal(e.points, ek.read_curve(out))
    tilted = ek.embed("3_1", tilt=90.0, vertices=100, output=str(tmp_path / "t.obj"))
    assert tilted.output == str(tmp_path / "t.obj")
    assert np.array_equal(tilted.points, ek.read_curve(tilted.output))
    assert tilted.alexander == [1, -1, 1]
    cylinder = knots.json("embed", "9_40", "--style", "cylinder", "-n", "300", "-o", str(tmp_path / "c.obj"))
    c = ek.embed("9_40", style="cylinder", vertices=300)
    assert {k: v for k, v in c.to_dict().items() if k != "points"} == {
        k: v for k, v in cylinder.items() if k != "output"}
    assert np.array_equal(c.points, ek.read_curve(str(tmp_path / "c.obj")))


def test_embed_of_a_link_equals_the_cli(knots, tmp_path):
    """A link of the link table: the command's keys and one array per component, as read_link reads them."""
    for source in ("braid", "pd"):
        out = str(tmp_path / f"borromean-{source}.obj")
        cli = knots.json("embed", "borromean", "--from", source, "-n", "240", "-o", out)
        e = ek.embed("borromean", from_=source, vertices=240, output=out + ".py.obj")
        assert {k: v for k, v in e.to_dict().items() if k not in ("points", "output")} == {
            k: v for k, v in cli.items() if k != "output"}
        assert list(e.to_dict())[:-1] == list(cli)  # the command's key order, points last
        assert len(e.points) == 3 and sum(len(P) for P in e.points) == e.vertices
        for P, Q, R in zip(e.points, ek.read_link(out), ek.read_link(out + ".py.obj")):
            assert np.array_equal(P, Q) and np.array_equal(P, R)
        assert e.linking_numbers == ek.knot("borromean").linking_numbers


def test_sample_equals_the_cli(knots, tmp_path):
    cli = knots.json("sample", "4_1", "--count", "3", "-n", "60", "--seed", "7", "-o", str(tmp_path))
    samples = ek.sample("4_1", count=3, vertices=60, seed=7)
    assert len(samples) == 3
    for array, path in zip(samples, cli["files"]):
        assert array.shape == (60, 3)
        assert np.array_equal(array, ek.read_curve(path))
        assert np.array_equal(array, np.round(array))  # lattice sites
        assert np.allclose(np.linalg.norm(np.roll(array, -1, axis=0) - array, axis=1), 1.0)
        assert ek.alexander(array) == [-1, 3, -1]


def test_sample_from_a_curve_equals_the_cli(knots, curve_file, tmp_path):
    path = curve_file(trefoil(200), "t.obj")
    cli = knots.json("sample", path, "--count", "2", "-n", "80", "-o", str(tmp_path / "s"))
    samples = ek.sample(ek.read_curve(path), count=2, vertices=80)
    for array, file in zip(samples, cli["files"]):
        assert np.array_equal(array, ek.read_curve(file))


def test_bad_input_is_a_value_error_with_the_cli_message(knots, curve_file, tmp_path):
    with pytest.raises(ValueError) as e:
        ek.sample("3_1", vertices=61)
    assert str(e.value) == knots.error("sample", "3_1", "-n", "61", "-o", str(tmp_path))
    with pytest.raises(ValueError, match="shape"):
        ek.invariants(np.zeros((10, 2)))
    with pytest.raises(ValueError, match="at least 4 vertices"):
        ek.writhe(np.eye(3))
    bad = trefoil()
    bad[5] = np.nan
    with pytest.raises(ValueError, match="not finite"):
        ek.alexander(bad)
    with pytest.raises(ValueError) as e:
        ek.embed("3_1", from_="dt")
    assert str(e.value) == knots.error("embed", "3_1", "--from", "dt", "-o", str(tmp_path / "x.obj"))
