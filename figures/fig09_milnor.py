"""Fig. 9: for each knot type, the equilibrium with the smallest total
curvature divided by Milnor's bound 2π·bridge index; BB knots (bridge index =
braid index) in their own colour, 2-bridge knots marked."""
import numpy as np

from common import flag, parse_args, plt, read_csv, read_summary, save

a = parse_args(__doc__)
rows = read_csv(f"{a.results}/milnor/milnor.csv")
summary = read_summary(a.results, "milnor")
ratio = np.array([float(r["ratio"]) for r in rows])
bb = np.array([bool(flag(r["bb"])) for r in rows], dtype=bool)
two = np.array([bool(flag(r["two_bridge"])) for r in rows], dtype=bool)
fig, ax = plt.subplots(figsize=(6.5, 3.2))
bins = np.linspace(1.0, max(1.05, ratio.max() * 1.02), 40)
ax.hist([ratio[bb], ratio[~bb & ~two], ratio[~bb & two]], bins=bins, stacked=True,
        color=["tab:orange", "lightsteelblue", "navy"],
        label=[f"BB knots ({bb.sum()})", f"other knots ({(~bb & ~two).sum()})", f"2-bridge, not BB ({(~bb & two).sum()})"])
ax.axvline(1.0, color="k", lw=0.8, ls="--")
ax.set_xlabel("min total curvature / (2π · bridge index)")
ax.set_ylabel("knot types")
full = summary.get("full_budget_knots", 0)  # knots sampled again at the full budget (the far end)
ax.set_title(f"Milnor's bound, {len(rows)} knot types ({summary['equilibria']} equilibria, "
             f"{summary['milnor_violations']} violations"
             + ")" + (f"\n{full} knots sampled again at the full budget of {summary['budget']}" if full else ""), fontsize=9)
ax.legend(fontsize=8)
ax.yaxis.set_major_locator(plt.MaxNLocator(integer=True))
save(fig, a.out, "fig09_milnor")
