"""Section 8.2: distribution of the 3D-ness of all equilibria of the data set;
equilibria left of the threshold count as approximately planar."""
import numpy as np

from common import parse_args, plt, read_csv, read_summary, save

a = parse_args(__doc__)
values = np.array([float(r["threedim"]) for r in read_csv(f"{a.results}/planarity/threedim.csv")])
s = read_summary(a.results, "planarity")
fig, ax = plt.subplots(figsize=(5.5, 3.0))
ax.hist(values, bins=np.linspace(0, 1, 41), color="tab:blue")
ax.axvline(s["threshold"], color="k", ls="--", lw=0.8, label=f"planar below {s['threshold']}")
ax.set_xlabel("3D-ness (shortest / longest edge of the oriented bounding box)")
ax.set_ylabel("equilibria")
ax.set_title(f"{s['planar']} of {s['equilibria']} equilibria planar ({100 * s['planar_share']:.0f}%)", fontsize=9)
ax.legend(fontsize=8)
save(fig, a.out, "fig_planarity")
