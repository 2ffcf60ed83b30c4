"""Load a data set, list per knot its lowest-energy and its most 3D state,
and plot the Milnor histogram.

The counterpart of the analysis demo of the paper's code (Demo-2B-Analysis in
EPFL-LGG/ElasticKnots): the attributes of every equilibrium as numpy columns,
the extreme states per knot type, and the distribution of the smallest total
curvature over Milnor's bound 2π·bridge index (paper Fig. 9). A plain script;
each "# %%" block is a notebook cell.

    PYTHONPATH=build/python python3 docs/examples/analyze_dataset.py [DATASET.h5 [milnor.png]]

DATASET.h5 defaults to the data set of `make figures`
(results/default/dataset/dataset.h5); the histogram is written to
milnor.png (or shown, in a notebook).
"""
# %% Load the data set
import sys

import matplotlib
import numpy as np

if "ipykernel" not in sys.modules:
    matplotlib.use("Agg")  # a script writes the figure to a file
import matplotlib.pyplot as plt

import elastic_knots as ek

path = sys.argv[1] if len(sys.argv) > 1 else "results/default/dataset/dataset.h5"
figure = sys.argv[2] if len(sys.argv) > 2 else "milnor.png"

ds = ek.Dataset(path)
p = ds.describe().parameters
print(f"{path}: {len(ds)} knots; n = {p.vertices}, r = {p.radius}, E = {p.young}, sampling {p.sampling}")
cols = ds.attributes()  # knot, index and one numpy column per attribute
print(f"{len(cols.knot)} equilibria; attributes: {', '.join(k for k in cols.keys() if k not in ('knot', 'index'))}")


# %% Per knot type: the state of lowest energy and the most 3D state
def extreme(values, largest):
    """Per knot, the row of the smallest (largest) value."""
    rows = []
    for name in ds.knots:
        idx = np.flatnonzero(cols.knot == name)
        if idx.size:
            rows.append(idx[np.argmax(values[idx]) if largest else np.argmin(values[idx])])
    return rows


print(f"\n{'knot':10} {'lowest energy':>14} {'(state)':>7}   {'most 3D':>8} {'(state)':>7}")
for low, high in zip(extreme(cols.energy, False), extreme(cols.threedim, True)):
    print(f"{cols.knot[low]:10} {cols.energy[low]:14.6g} {cols.index[low]:7d}   "
          f"{cols.threedim[high]:8.4f} {cols.index[high]:7d}")

# the same with the query syntax of `knots query`: the five most 3D states of the data set
for row in ds.query(sort="threedim:desc", limit=5).rows:
    print(f"  {row.knot} state {row.index}: threedim {row.threedim:.4f}, energy {row.energy:.6g}")

# %% Milnor: per knot the smallest total curvature over 2π·bridge index (> 1 for every knot);
# BB knots (bridge index = braid index) reach the bound as multi-covered circles
names, ratio, bb = [], [], []
for row in extreme(cols.total_curvature, False):
    k = ek.knot(str(cols.knot[row]))
    if k.bridge_index is None:
        continue
    names.append(k.name)
    ratio.append(cols.total_curvature[row] / (2.0 * np.pi * k.bridge_index))
    bb.append(k.bridge_index == k.braid_index)
ratio, bb = np.array(ratio), np.array(bb, dtype=bool)
print(f"\nMilnor ratio: smallest {ratio.min():.5f} ({names[int(np.argmin(ratio))]}), "
      f"largest {ratio.max():.5f} ({names[int(np.argmax(ratio))]}); {bb.sum()} BB knots")
assert np.all(ratio > 1.0), "Milnor's bound is violated"

fig, ax = plt.subplots(figsize=(6, 3.5))
bins = np.linspace(1.0, max(ratio.max(), 1.01), 41)
ax.hist(ratio[~bb], bins=bins, color="C0", label=f"non-BB knot types ({(~bb).sum()})")
ax.hist(ratio[bb], bins=bins, color="C1", label=f"BB knot types ({bb.sum()})")
ax.set_xlabel(r"$\int \kappa \,/\, 2\pi b$ (smallest per knot type)")
ax.set_ylabel("knot types")
ax.set_title("Milnor's bound")
ax.legend()
fig.tight_layout()
if "ipykernel" in sys.modules:
    plt.show()
else:
    fig.savefig(figure, dpi=150)
    print(f"wrote {figure}")
