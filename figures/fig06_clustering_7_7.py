"""Fig. 6: hierarchical clustering of the equilibria of 7_7: the pairwise
similarity matrix in dendrogram order, the complete-linkage dendrogram with
the cut, and the 2D multidimensional scaling coloured by cluster."""
import numpy as np

from common import load_equilibria, parse_args, plt, read_csv, read_summary, save

KNOT = "7_7"
a = parse_args(__doc__)
_, _, sim, link = load_equilibria(f"{a.results}/multistability/multistability.h5", KNOT)
mds = read_csv(f"{a.results}/multistability/mds_{KNOT}.csv")
cut = read_summary(a.results, "multistability")["cut"]
n = sim.shape[0]
order = np.argsort([int(r["leaf_position"]) for r in mds])
fig, (ax0, ax1, ax2) = plt.subplots(1, 3, figsize=(12, 3.8))
# MDS scatter
xs = np.array([float(r["x"]) for r in mds])
ys = np.array([float(r["y"]) for r in mds])
cl = np.array([int(r["cluster_rank"]) for r in mds])
sc = ax0.scatter(xs, ys, c=cl, cmap="tab20", s=18)
ax0.set_title("multidimensional scaling", fontsize=9)
ax0.set_xlabel("MDS 1")
ax0.set_ylabel("MDS 2")
# dendrogram drawn from the linkage matrix (SciPy layout [a, b, height, size])
pos = {int(leaf): float(p) for p, leaf in enumerate(order)}
height = {i: 0.0 for i in range(n)}
for k, (ca, cb, h, _) in enumerate(link):
    ca, cb = int(ca), int(cb)
    xa, xb = pos[ca], pos[cb]
    ax1.plot([xa, xa, xb, xb], [height[ca], h, h, height[cb]], color="k", lw=0.7)
    pos[n + k] = 0.5 * (xa + xb)
    height[n + k] = h
ax1.axhline(cut, color="tab:red", ls="--", lw=0.8, label=f"cut {cut}")
ax1.set_xlabel("equilibria (dendrogram order)")
ax1.set_ylabel("distance 1 - similarity")
ax1.set_title("complete linkage", fontsize=9)
ax1.legend(fontsize=8)
# similarity matrix
im = ax2.imshow(sim[np.ix_(order, order)], cmap="magma", vmin=0, vmax=1)
ax2.set_title("similarity (dendrogram order)", fontsize=9)
fig.colorbar(im, ax=ax2, fraction=0.046)
fig.suptitle(f"{KNOT}: {n} equilibria, {cl.max() + 1 if n else 0} clusters at the cut", fontsize=10)
save(fig, a.out, "fig06_clustering_7_7")
