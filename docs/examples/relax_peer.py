"""Relax a curve of the peer implementation and print its energy.

The counterpart of the simulation demo of the paper's code (Demo-1-Simulation
in EPFL-LGG/ElasticKnots): load a centerline, relax it to a stable equilibrium
of the twist-free elastic rod with self-contact, print the energy and its
parts. A plain script; each "# %%" block is a notebook cell.

    PYTHONPATH=build/python python3 docs/examples/relax_peer.py [CURVE [OUT]]

CURVE defaults to the peer's 4_1-smooth.obj in ../shared/data/peer/ next to
the repository (or $EK_PEER_DATA), read where it is; OUT (optional) receives
the equilibrium.
"""
# %% Load the centerline
import os
import sys

import numpy as np

import elastic_knots as ek

here = os.path.dirname(os.path.abspath(__file__))
peer = os.environ.get("EK_PEER_DATA", os.path.join(here, "..", "..", "..", "shared", "data", "peer"))
path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(peer, "4_1-smooth.obj")
out = sys.argv[2] if len(sys.argv) > 2 else None

centerline = ek.read_curve(path)  # (n, 3) float array
edges = np.linalg.norm(np.roll(centerline, -1, axis=0) - centerline, axis=1)
print(f"{os.path.basename(path)}: {len(centerline)} vertices, length {edges.sum():.6g}, "
      f"Alexander {ek.alexander(centerline)}")

# %% The energy of the start: r = 0.2, E = 2000, nu = 0.3 (the paper's material, the defaults);
# contact distance 2r and stiffness 1e3 as in the paper
start = ek.energy(centerline)
print(f"start:       energy {start.energy:.10g} (bend {start.energy_bend:.6g}, "
      f"stretch {start.energy_stretch:.6g}, contact {start.energy_contact:.6g}), "
      f"gradient norm {start.gradient_norm:.3g}")

# %% Relax: Newton with the collision-free line search; the edge lengths are the rest lengths
result = ek.relax(centerline, output=out)
print(f"equilibrium: {result.status} after {result.total_iterations} iterations ({result.seconds:.3g} s)")
print(f"energy:      {result.energy:.10g} (bend {result.energy_bend:.6g}, stretch {result.energy_stretch:.6g}, "
      f"twist {result.energy_twist:.6g}, contact {result.energy_contact:.6g})")
print(f"writhe {result.writhe:.6g}, {result.contacts} contacts, Alexander preserved: {result.alexander_preserved}")
if out:
    print(f"wrote {out}")

# %% The equilibrium's energy, recomputed from its positions: energy() takes the
# equilibrium's own edges as rest lengths (no stretching), while the relaxation kept
# the start's; the edges stretched by ~1e-6 relative, so the two agree to ~1e-5
again = ek.energy(result.points)
assert abs(again.energy - result.energy) <= 1e-5 * result.energy, (again.energy, result.energy)
assert result.converged and result.alexander_preserved and result.energy < start.energy
