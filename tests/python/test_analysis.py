"""The contact and analysis bindings: ccd, similarity, similarity_matrix,
cluster, mds and attributes, on known answers and against the knots command."""
import numpy as np
import pytest

import elastic_knots as ek
from conftest import trefoil


def rotation(axis, angle):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K


def moved_copy(P):
    """P rotated, translated and cyclically re-indexed."""
    return np.roll(P @ rotation([1, 2, 3], 0.7).T + np.array([5.0, -2.0, 1.0]), 17, axis=0)


def test_ccd_equals_the_cli(knots, curve_file):
    P = trefoil()
    start = curve_file(P, "start.obj")
    for end_points in [P + np.array([3.0, 0.0, 0.0]), P * np.array([1.0, 1.0, -1.0])]:
        end = curve_file(end_points, "end.obj")
        r = ek.ccd(P, end_points, radius=0.3, separation=0.2)
        cli = knots.json("ccd", start, end, "--radius", "0.3", "--separation", "0.2")
        del cli["start"], cli["end"]
        assert r.to_dict() == cli
    assert ek.ccd(P, P + 3.0).full_step and ek.ccd(P, P + 3.0).t == 1.0  # a translation never collides
    flipped = ek.ccd(P, P * np.array([1.0, 1.0, -1.0]))  # the strands must pass through each other
    assert flipped.t < 1.0 and len(flipped.limiting_edges) == 2
    with pytest.raises(ValueError, match="vertices"):
        ek.ccd(P, P[:-1])


def test_similarity_of_a_moved_copy_is_one(knots, curve_file):
    P = trefoil()
    Q = moved_copy(P)
    r = ek.similarity(P, Q)
    assert r.similarity == 1.0 and r.samples == len(P)
    assert r.best_shift == 17
    cli = knots.json("similarity", curve_file(P, "a.obj"), curve_file(Q, "b.obj"))
    del cli["file_a"], cli["file_b"]
    assert r.to_dict() == cli
    other = ek.embed("4_1", vertices=120).points
    for kwargs, args in [({"reverse": True, "mirror": True}, ["--reverse", "--mirror"]),
                         ({"samples": 90}, ["--samples", "90"])]:
        cli = knots.json("similarity", curve_file(P, "a.obj"), curve_file(other, "c.obj"), *args)
        del cli["file_a"], cli["file_b"]
        assert ek.similarity(P, other, **kwargs).to_dict() == cli
    assert ek.similarity(P, other).similarity < 0.99
    mirror = ek.similarity(P, P * np.array([1.0, 1.0, -1.0]), mirror=True)
    assert mirror.similarity == 1.0 and mirror.mirrored


def test_similarity_matrix_cluster_and_mds():
    P = trefoil()
    curves = [P, moved_copy(P), ek.embed("4_1", vertices=120).points, ek.embed("5_1", vertices=120).points]
    S = ek.similarity_matrix(curves)
    assert S.shape == (4, 4)
    assert np.array_equal(S, S.T) and np.all(np.diag(S) == 1.0)
    assert S[0, 1] == 1.0
    assert S[0, 2] == pytest.approx(ek.similarity(curves[0], curves[2]).similarity, abs=1e-15)
    c = ek.cluster(S, cut=1e-9)
    assert c.linkage.shape == (3, 4)
    assert c.linkage[0].tolist() == [0.0, 1.0, 0.0, 2.0]  # the copies merge first, at distance 0
    assert c.labels.tolist() == [0, 0, 1, 2] and c.count == 3
    assert sorted(c.leaf_order.tolist()) == [0, 1, 2, 3]
    assert "labels" not in ek.cluster(S)


def test_cluster_and_mds_known_answers():
    S = np.array([[1.0, 0.95, 0.1], [0.95, 1.0, 0.12], [0.1, 0.12, 1.0]])
    c = ek.cluster(S, cut=0.2)
    assert c.labels.tolist() == [0, 0, 1] and c.count == 2
    assert c.linkage[0].tolist() == pytest.approx([0.0, 1.0, 0.05, 2.0])
    assert c.linkage[1].tolist() == pytest.approx([2.0, 3.0, 0.9, 3.0])  # complete linkage: max(0.9, 0.88)
    x = np.array([0.0, 0.1, 0.25, 0.7, 0.75])  # points on a line: D = |xi - xj| is Euclidean
    D = np.abs(x[:, None] - x[None, :])
    m = ek.mds(1.0 - D, dims=1)
    y = m.coordinates[:, 0]
    assert np.allclose(np.abs(y[:, None] - y[None, :]), D, atol=1e-12)
    assert m.explained == pytest.approx(1.0) and m.converged
    with pytest.raises(ValueError, match="square"):
        ek.mds(np.ones((2, 3)))
    with pytest.raises(ValueError, match="cut"):
        ek.cluster(S, cut=1.5)


def test_attributes_equal_the_cli(knots, curve_file):
    P = trefoil()
    r = ek.attributes(P, radius=0.3, young=1000.0)
    cli = knots.json("attributes", curve_file(P), "--radius", "0.3", "--young", "1000")
    del cli["file"]
    assert r.to_dict() == cli
    t = np.linspace(0.0, 2.0 * np.pi, 100, endpoint=False)
    circle = np.column_stack([np.cos(t), np.sin(t), np.zeros_like(t)])
    a = ek.attributes(circle)
    assert a.threedim == 0.0 and a.sphericity == pytest.approx(0.0, abs=1e-12)
    assert a.total_curvature == pytest.approx(2.0 * np.pi, rel=1e-12)
    assert a.energy is None and a.stiffness is None
    with pytest.raises(ValueError) as e:
        ek.attributes(P, radius=0.0)
    assert str(e.value) == knots.error("attributes", curve_file(P), "--radius", "0")
