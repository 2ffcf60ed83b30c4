"""Links from Python (docs/python.md): link files read and written as lists of
arrays, the linking number with its sign, and relax_link equal to `knots relax`
on the same link file (the Borromean rings embedded from their braid word)."""
import numpy as np
import pytest

import elastic_knots as ek
from conftest import json_part, without_times


def circle(n, centre, radius, u, v):
    t = 2.0 * np.pi * np.arange(n) / n
    return np.asarray(centre) + radius * (np.outer(np.cos(t), u) + np.outer(np.sin(t), v))


def test_link_files_and_the_linking_number(tmp_path):
    a = circle(48, [0, 0, 0], 1.0, [1, 0, 0], [0, 1, 0])
    b = circle(40, [1, 0, 0], 1.0, [1, 0, 0], [0, 0, 1])  # crosses a's disc downwards
    assert ek.linking_number(a, b) == pytest.approx(-1.0, abs=1e-9)
    assert ek.linking_number(a, b[::-1]) == pytest.approx(1.0, abs=1e-9)
    for ext in ("obj", "txt"):
        path = str(tmp_path / f"hopf.{ext}")
        ek.write_link(path, [a, b])
        back = ek.read_link(path)
        assert len(back) == 2 and np.array_equal(back[0], a) and np.array_equal(back[1], b)
    ek.write_link(str(tmp_path / "one.obj"), [a])
    assert np.array_equal(ek.read_curve(str(tmp_path / "one.obj")), a)
    with pytest.raises(ValueError, match="touch or cross"):
        ek.write_link(str(tmp_path / "cross.txt"), [a, circle(40, [1, 0, 0], 1.0, [1, 0, 0], [0, 1, 0])])
        ek.read_link(str(tmp_path / "cross.txt"))


def test_relax_link_equals_the_cli(knots, tmp_path):
    src = str(tmp_path / "borromean.obj")
    knots.json("embed", "--braid", "1,-2,1,-2,1,-2", "-n", "180", "-o", src)
    out = str(tmp_path / "relaxed.obj")
    r = ek.relax_link(ek.read_link(src), output=out)
    cli = knots.json("relax", src)
    mine = without_times({k: v for k, v in json_part(r).items() if k not in ("output", "points")})
    assert mine == without_times({k: v for k, v in cli.items() if k != "file"})
    assert r.status == "converged-stable" and r.components == 3
    assert r.linking_numbers == [[0, 0, 0], [0, 0, 0], [0, 0, 0]] and r.alexander == [[1], [1], [1]]
    assert len(r.points) == 3 and sum(p.shape[0] for p in r.points) == r.vertices
    back = ek.read_link(out)
    assert all(np.array_equal(p, q) for p, q in zip(back, r.points))
    with pytest.raises(ValueError, match="at least 2 components"):
        ek.relax_link([r.points[0]])


def test_a_link_data_set_reads_with_its_components(knots, tmp_path):
    path = str(tmp_path / "links.h5")
    knots.json("explore", "borromean", "--samples", "2", "-n", "180", "--quiet", "-o", path)
    d = ek.Dataset(path)
    assert d.knots == ["borromean"]
    k = d.knot("borromean")
    assert k.components == [60, 60, 60]
    assert k.conway == [0, 0, 0, 0, 1]  # z⁴
    assert k.linking_numbers == [[0, 0, 0], [0, 0, 0], [0, 0, 0]]
    assert k.equilibria.shape[1:] == (180, 3)
    assert "min_distance" in k.attributes
