"""relax() and sample() release the GIL: in a thread pool they give the same
results as one after the other (the speed-up is measured by
bench/python_thread_pool.py, not asserted here)."""
from concurrent.futures import ThreadPoolExecutor

import numpy as np

import elastic_knots as ek
from conftest import trefoil


def test_relax_in_a_thread_pool_equals_sequential_relaxations():
    curves = [trefoil(100), ek.embed("4_1", vertices=100).points, ek.embed("5_2", from_="pd", vertices=100).points]
    sequential = [ek.relax(P) for P in curves]
    with ThreadPoolExecutor(max_workers=3) as pool:
        parallel = list(pool.map(ek.relax, curves))
    for s, p in zip(sequential, parallel):
        assert np.array_equal(s.points, p.points)
        assert s.energy == p.energy and s.total_iterations == p.total_iterations


def test_sample_in_a_thread_pool_equals_sequential_samples():
    seeds = [1, 2, 3]
    sequential = [ek.sample("5_1", count=2, vertices=60, seed=s) for s in seeds]
    with ThreadPoolExecutor(max_workers=3) as pool:
        parallel = list(pool.map(lambda s: ek.sample("5_1", count=2, vertices=60, seed=s), seeds))
    for s, p in zip(sequential, parallel):
        assert all(np.array_equal(a, b) for a, b in zip(s, p))
