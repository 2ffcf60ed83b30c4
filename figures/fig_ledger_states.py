"""The distinct states of one knot from the committed ledgers (the look of
the paper's Fig. 2): every state whose curve the ledger keeps, sorted by
energy, drawn from the top of its principal frame as a tube of the wire's
radius coloured by curvature, with its energy, member count and 3D-ness.
Reads RESULTS/ledgers/*.ledger.h5 (docs/dataset-format.md, "Ledgers")."""
import argparse
import glob
import os

import h5py
import numpy as np

import render
from common import draw_curve, plt, save


def ledger_knot(folder, knot):
    """(curves, energies, members, threedim, radius) of the knot's states with kept curves, from its ledger."""
    for path in sorted(glob.glob(os.path.join(folder, "*.ledger.h5"))):
        with h5py.File(path, "r") as f:
            if f"knots/{knot}" not in f:
                continue
            rows = f[f"knots/{knot}"].attrs["rows"]
            first_eq, first_state, states = int(rows[2]), int(rows[5]), int(rows[6])
            names = [n.decode() if isinstance(n, bytes) else n for n in f["equilibria/attribute_names"][:]]
            attributes = f["equilibria/attributes"]
            quantum = float(f.attrs["curve_quantum"])
            out = []
            for s in range(first_state, first_state + states):
                c = int(f["states/curve"][s])
                if c < 0:
                    continue
                row = first_eq + int(f["states/representative"][s])
                steps = f["curves/steps"][c].astype(np.int64)
                grid = np.vstack([f["curves/origin"][c], steps]).cumsum(axis=0)
                out.append((quantum * grid, attributes[row, names.index("energy")], int(f["states/members"][s]),
                            attributes[row, names.index("threedim")]))
            return out, float(f.attrs["radius"])
    raise SystemExit(f"fig_ledger_states.py: no ledger in {folder} holds {knot}")


p = argparse.ArgumentParser(description=__doc__)
p.add_argument("--results", required=True, help="a results folder with ledgers/ (e.g. docs/results/sample12)")
p.add_argument("--knot", required=True, help="the knot, e.g. 12a_81")
p.add_argument("--out", required=True, help="output folder")
p.add_argument("--count", type=int, default=12, help="states drawn at most (the lowest in energy)")
a = p.parse_args()
os.makedirs(a.out, exist_ok=True)
render.cache_dir = os.path.join(a.out, ".render-cache")
states, radius = ledger_knot(os.path.join(a.results, "ledgers"), a.knot)
states = states[: a.count]
cols = min(6, len(states))
rows = (len(states) + cols - 1) // cols
fig, axs = plt.subplots(rows, cols, figsize=(2.0 * cols, 2.2 * rows), squeeze=False)
for ax in axs.flat:
    ax.axis("off")
for ax, (P, energy, members, threedim) in zip(axs.flat, states):
    draw_curve(ax, P, radius=radius, radius_scale=4.0, view="top")
    ax.set_title(f"E {energy:.4f}, {members}×, 3D {threedim:.2f}", fontsize=7)
fig.suptitle(f"{a.knot}: the {len(states)} lowest of its distinct states (tubes at 4× the wire radius)", fontsize=9)
save(fig, a.out, f"states_{a.knot}")
