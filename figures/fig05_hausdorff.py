"""Fig. 5: the Hausdorff distance against the similarity measure on 6_1's
equilibria. Left: the pairs of distinct states (different clusters, and
farther apart than the cut in similarity) that are closest in Hausdorff
distance after rigid alignment, drawn on top of each other, with both
numbers. Right: every pair, Hausdorff distance against 1 - similarity; the
similarity's cut and the median Hausdorff distance of pairs within one state,
over the unique equilibria (an equilibrium that several samples reach counted
once; the claim) and over every equilibrium."""
from common import dataset_material, draw_framed, frame_of, parse_args, plt, read_csv, read_obj, read_summary, save, flag

a = parse_args(__doc__)
s = read_summary(a.results, "hausdorff")
radius, _ = dataset_material(f"{a.results}/hausdorff/hausdorff.h5")
rows = read_csv(f"{a.results}/hausdorff/pairs.csv")
shown = s["shown"][:2]

fig = plt.figure(figsize=(4.0 + 2.6 * max(len(shown), 1), 4.4))
grid = fig.add_gridspec(2, len(shown) + 2, width_ratios=[1.0] * len(shown) + [0.15, 1.8])
for col, p in enumerate(shown):
    A = read_obj(f"{a.results}/hausdorff/{p['curve_a']}")
    B = read_obj(f"{a.results}/hausdorff/{p['curve_b']}")  # aligned onto A
    frame = frame_of(A)
    for row, view in enumerate(("top", "front")):
        ax = fig.add_subplot(grid[row, col])
        draw_framed(ax, A, view, frame, radius=radius, color="tab:blue", label=f"#{p['a']} (state {p['cluster_a'] + 1})")
        draw_framed(ax, B, view, frame, radius=radius, color="tab:orange", label=f"#{p['b']} (state {p['cluster_b'] + 1})")
        if row == 0:
            ax.set_title(f"Hausdorff {p['hausdorff']:.2f}\n1 − similarity {p['similarity_distance']:.3f}", fontsize=8)
            ax.legend(fontsize=6, loc="lower center", bbox_to_anchor=(0.5, -0.25), frameon=False)
        ax.set_ylabel(view if col == 0 else "", fontsize=7)
ax = fig.add_subplot(grid[:, -1])
same = [r for r in rows if flag(r["same_cluster"])]
other = [r for r in rows if not flag(r["same_cluster"])]
ax.scatter([float(r["hausdorff"]) for r in other], [float(r["similarity_distance"]) for r in other], s=3,
           color="tab:red", alpha=0.4, label="different states", lw=0)
ax.scatter([float(r["hausdorff"]) for r in same], [float(r["similarity_distance"]) for r in same], s=4,
           color="tab:blue", alpha=0.7, label="same state", lw=0)
ax.axhline(s["cut"], color="k", lw=0.8, ls="--", label=f"cut {s['cut']}")
if s["median_unique_same_cluster_hausdorff"] is not None:
    ax.axvline(s["median_unique_same_cluster_hausdorff"], color="tab:blue", lw=0.8, ls="--",
               label=f"median Hausdorff, same state ({s['median_unique_same_cluster_hausdorff']:.2f})")
if s["median_same_cluster_hausdorff"] is not None:
    ax.axvline(s["median_same_cluster_hausdorff"], color="tab:blue", lw=0.8, ls=":",
               label=f"the same with duplicates ({s['median_same_cluster_hausdorff']:.2f})")
for p in shown:
    ax.scatter([p["hausdorff"]], [p["similarity_distance"]], s=40, facecolors="none", edgecolors="k", lw=0.8)
    ax.annotate(f"{p['a']}/{p['b']}", (p["hausdorff"], p["similarity_distance"]), fontsize=6,
                xytext=(4, 4), textcoords="offset points")
ax.set_xscale("symlog", linthresh=1.0)  # pairs within a state and across far-apart states both visible
ax.set_xlabel("Hausdorff distance after alignment\n[edge lengths; linear below 1]", fontsize=8)
ax.set_ylabel("1 − similarity", fontsize=8)
ax.tick_params(labelsize=7)
ax.legend(fontsize=6, loc="center right")
fig.suptitle(f"{s['knot']}: {s['equilibria']} equilibria ({s['unique_equilibria']} unique), {s['clusters']} states at "
             f"cut {s['cut']}; below the median Hausdorff distance within a state: {s['below_unique_median_pairs']} of "
             f"{s['unique_different_cluster_pairs']} pairs of different states,\n"
             f"{s['separated_below_unique_median']} of them also farther apart than the cut in similarity "
             f"(left: of those farther apart than the cut, the closest in Hausdorff distance)", fontsize=8)
save(fig, a.out, "fig05_hausdorff")
