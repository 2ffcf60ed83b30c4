"""Dataset: a data set read from Python equals what the knots command reads
(describe, query, cluster, export)."""
import numpy as np
import pytest

import elastic_knots as ek


@pytest.fixture(scope="module")
def ds(dataset_path):
    return ek.Dataset(dataset_path)


def test_describe_equals_the_cli(ds, knots, dataset_path):
    d = ds.describe()
    assert d.to_dict() == knots.json("describe", dataset_path)
    assert ds.knots == d.knots and len(ds) == len(d.knots)
    assert d.parameters.vertices == 100 and d.parameters.radius == 0.2
    assert all(name in ds for name in ds.knots) and "13_1" not in ds


@pytest.mark.parametrize("kwargs,args", [
    ({}, []),
    ({"sort": "energy", "limit": 5}, ["--sort", "energy", "--limit", "5"]),
    ({"where": "threedim>0.05", "sort": "total_curvature:desc"},
     ["--where", "threedim>0.05", "--sort", "total_curvature:desc"]),
    ({"knot": "4_1", "where": ["energy<1e9", "writhe!=0"]}, ["--knot", "4_1", "--where", "energy<1e9",
                                                               "--where", "writhe!=0"]),
    ({"where": "threedim>=2"}, ["--where", "threedim>=2"]),
])
def test_query_equals_the_cli(ds, knots, dataset_path, kwargs, args):
    q = ds.query(**kwargs)
    assert q.to_dict() == knots.json("query", dataset_path, *args)
    assert q.count == len(q.rows)


def test_clusters_equal_the_cli(ds, knots, dataset_path):
    for name in ds.knots:
        for cut in (0.02, 0.1):
            c = ds.clusters(name, cut=cut)
            assert c.to_dict() == knots.json("cluster", dataset_path, name, "--cut", cut)
            assert sorted(i for cl in c.clusters for i in cl.members) == list(range(c.equilibria))


def test_equilibria_equal_the_exported_curves(ds, knots, dataset_path, tmp_path):
    name = ds.knots[1]
    eq = ds.equilibria(name)
    assert eq.ndim == 3 and eq.shape[1:] == (100, 3) and eq.shape[0] > 0
    for i in (0, eq.shape[0] - 1):
        out = str(tmp_path / f"{i}.obj")
        status, _, err = knots.run("export", dataset_path, name, i, "-o", out)
        assert status == 0, err
        assert np.array_equal(eq[i], ek.read_curve(out))
    assert ek.alexander(eq[0]) == ek.knot(name).alexander


def test_attribute_columns_equal_the_query_rows(ds):
    cols = ds.attributes()
    rows = ds.query().rows
    assert len(cols.knot) == len(rows)
    assert cols.knot.tolist() == [r.knot for r in rows]
    assert cols.index.tolist() == [r.index for r in rows]
    for name in ("energy", "threedim", "total_curvature", "writhe"):
        assert np.array_equal(cols[name], np.array([r[name] for r in rows], dtype=float))
    one = ds.attributes(knot="3_1")
    assert set(one.knot.tolist()) == {"3_1"}


def test_knot_entry(ds):
    k = ds.knot("4_1")
    m = k.equilibria.shape[0]
    assert k.crossing_number == 4 and k.bridge_index == 2 and k.alexander == [-1, 3, -1]
    assert k.similarity.shape == (m, m) and np.all(np.diag(k.similarity) == 1.0)
    assert k.linkage.shape == (m - 1, 4)
    assert len(k.runs.status) == k.samples_used
    stored = k.runs.equilibrium[k.runs.equilibrium >= 0]
    assert sorted(stored.tolist()) == list(range(m))
    assert np.array_equal(k.attributes.energy, ds.attributes(knot="4_1").energy)


def test_bad_input_is_a_value_error_with_the_cli_message(ds, knots, dataset_path, tmp_path):
    with pytest.raises(ValueError) as e:
        ds.query(sort="colour")
    assert str(e.value) == knots.error("query", dataset_path, "--sort", "colour")
    with pytest.raises(ValueError) as e:
        ds.query(where="energy~1")
    assert str(e.value) == knots.error("query", dataset_path, "--where", "energy~1")
    with pytest.raises(ValueError) as e:
        ds.clusters("6_3", cut=0.1)
    assert str(e.value) == knots.error("cluster", dataset_path, "6_3", "--cut", "0.1")
    missing = str(tmp_path / "missing.h5")
    with pytest.raises(ValueError) as e:
        ek.Dataset(missing)
    assert str(e.value) == knots.error("describe", missing)
    with pytest.raises(ValueError) as e:
        ds.clusters("3_1", cut=1.5)
    assert str(e.value) == knots.error("cluster", dataset_path, "3_1", "--cut", "1.5")
