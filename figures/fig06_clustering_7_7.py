"""Fig. 6: hierarchical clustering of the equilibria of 7_7: the pairwise
similarity matrix in dendrogram order, the complete-linkage dendrogram with
the cut, the 2D multidimensional scaling coloured by cluster, and below them
the lowest-energy state of each cluster as a tube of the wire's radius (scaled
up, as the title says) in its cluster's colour."""
import numpy as np

from common import dataset_material, draw_curve, load_equilibria, parse_args, plt, read_csv, read_summary, save

KNOT = "7_7"
SCALE = 3.0  # wire drawn at this multiple of its radius
SHOWN = 10   # cluster representatives drawn, lowest energy first
a = parse_args(__doc__)
h5 = f"{a.results}/multistability/multistability.h5"
eq, _, sim, link = load_equilibria(h5, KNOT)
radius, _ = dataset_material(h5)
mds = read_csv(f"{a.results}/multistability/mds_{KNOT}.csv")
clusters = read_csv(f"{a.results}/multistability/clusters_{KNOT}.csv")
cut = read_summary(a.results, "multistability")["cut"]
n = sim.shape[0]
order = np.argsort([int(r["leaf_position"]) for r in mds])


def cluster_color(rank):
    return plt.cm.tab20(rank % 20)


shown = clusters[:SHOWN]
fig = plt.figure(figsize=(12, 6.2))
grid = fig.add_gridspec(2, 1, height_ratios=[1.0, 0.62], hspace=0.28)
top = grid[0].subgridspec(1, 3, wspace=0.3)
ax0, ax1, ax2 = (fig.add_subplot(top[0, k]) for k in range(3))
# MDS scatter
xs = np.array([float(r["x"]) for r in mds])
ys = np.array([float(r["y"]) for r in mds])
cl = np.array([int(r["cluster_rank"]) for r in mds])
ax0.scatter(xs, ys, c=[cluster_color(c) for c in cl], s=18)
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
# the clusters' lowest-energy states
bottom = grid[1].subgridspec(1, max(len(shown), 1), wspace=0.05)
for k, row in enumerate(shown):
    ax = fig.add_subplot(bottom[0, k])
    rank = int(row["rank"])
    draw_curve(ax, eq[int(row["representative"])], radius=radius, radius_scale=SCALE, view="top",
               color=cluster_color(rank)[:3])
    ax.set_title(f"cluster {rank + 1}: x{row['size']}\nE = {float(row['energy']):.4f}", fontsize=7,
                 color=cluster_color(rank))
fig.suptitle(f"{KNOT}: {n} equilibria, {cl.max() + 1 if n else 0} clusters at the cut; below, the lowest-energy "
             f"state of the {len(shown)} lowest clusters (wire drawn at {SCALE:g}× its radius r = {radius:g})",
             fontsize=10)
save(fig, a.out, "fig06_clustering_7_7")
