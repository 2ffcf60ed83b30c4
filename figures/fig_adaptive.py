"""Section 7.4: samples used per knot by adaptive sampling against the fixed
budget, and the importance score after each batch. The coverage of the
low-energy states (measured; the paper claims only the savings) is written
under the bars: the low-energy clusters of the full budget that the rule
found, and the share of the full budget's samples in the clusters it missed."""
import numpy as np

from common import parse_args, plt, read_csv, read_summary, save

a = parse_args(__doc__)
rows = read_csv(f"{a.results}/adaptive/adaptive.csv")
s = read_summary(a.results, "adaptive")
threshold = s["score_threshold"]
names = [r["knot"] for r in rows]
used = np.array([int(r["adaptive_samples"]) for r in rows])
fixed = np.array([int(r["fixed_samples"]) for r in rows])
fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(11, 3.4))
x = np.arange(len(rows))
ax0.bar(x, fixed, color="lightgray", label=f"fixed budget ({s['budget']})")
ax0.bar(x, used, color="tab:blue", label="adaptive")
ax0.set_xticks(x, names, rotation=90, fontsize=6)
ax0.set_ylabel("samples (simulations)")
ax0.set_title(f"saved {100 * s['saved_share']:.0f}% of the simulations, median {s['median_samples']} samples",
              fontsize=9)
ax0.legend(fontsize=8)
coverage = (f"low-energy clusters (within {s['low_energy_factor']} x the minimum energy) found: "
            f"{s['low_energy_clusters_found']} of {s['low_energy_clusters']}; the missed ones hold "
            f"{100 * s['missed_sample_share']:.1f}% of the full budget's samples")
fig.text(0.01, -0.08, coverage, fontsize=8)
for r in rows:
    scores = [float(v) for v in r["scores"].split(";") if v]
    ax1.plot(range(len(scores)), scores, marker=".", lw=0.8, alpha=0.6)
ax1.axhline(threshold, color="k", ls="--", lw=0.8, label=f"stop when S <= {threshold}")
ax1.set_xlabel("batch (0: initial samples)")
ax1.set_ylabel("importance score S")
ax1.legend(fontsize=8)
save(fig, a.out, "fig_adaptive")
