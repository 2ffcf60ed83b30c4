"""The distinct stable states of a knot type, from lattice samples.

The Python counterpart of examples/sample_states.cpp and of the pipeline of
the paper's Fig. 3 (Section 7): random cubic-lattice curves of the knot type
(BFACF), each relaxed to a stable equilibrium, compared by their
curvature-torsion signatures, clustered by complete linkage, listed by
energy. A plain script; each "# %%" block is a notebook cell.

    PYTHONPATH=build/python python3 docs/examples/sample_states.py [KNOT [SAMPLES]]

KNOT defaults to 5_2, SAMPLES to 8 (n = 100 vertices: seconds on 2 cores).
"""
# %% Sample the knot type on the lattice
import sys

import numpy as np

import elastic_knots as ek

name = sys.argv[1] if len(sys.argv) > 1 else "5_2"
count = int(sys.argv[2]) if len(sys.argv) > 2 else 8
samples = ek.sample(name, count=count, vertices=100, seed=1)  # count arrays of shape (100, 3)

# %% Relax each sample; keep the stable equilibria (the knot type is checked by relax)
states, energies = [], []
for s in samples:
    r = ek.relax(s)
    if r.status == "converged-stable":
        states.append(r.points)
        energies.append(r.energy)
print(f"{name}: {len(samples)} samples, {len(states)} stable equilibria")

# %% Compare (curvature-torsion similarity, orientation reversal) and cluster at the experiments' cut
if len(states) < 2:
    sys.exit(0 if states else 1)
S = ek.similarity_matrix(states, reverse=True)
c = ek.cluster(S, cut=0.05)
labels = np.asarray(c.labels)
lowest = sorted((min(energies[i] for i in np.flatnonzero(labels == k)), k) for k in range(c.count))
print(f"{c.count} distinct states at the cut 0.05")
for rank, (energy, k) in enumerate(lowest):
    print(f"  state {rank}: energy {energy:.6g}, {np.count_nonzero(labels == k)} samples")
