"""Transitions between stable states (paper Section 8.5, an open direction):
(a) energy along the minimum energy path of each verified index-1 saddle of
4_1's states, E - E_start in units of EI/L, from the start over the saddle to
the other minimum; (b) the start, saddle and end of the path with the highest
barrier, in the start's principal frame, as tubes coloured by curvature, with the
largest vertex displacement from the start."""
import numpy as np

from common import (curvature, dataset_material, draw_framed, frame_of, parse_args, plt, read_csv, read_obj, read_summary,
                    save, save_empty)

a = parse_args(__doc__)
d = f"{a.results}/saddles"
s = read_summary(a.results, "saddles")
profile = read_csv(f"{d}/profile.csv")
saddles = s["verified_saddles"]
if not saddles:
    save_empty(a.out, "fig_saddles", "no verified saddle at this scale")
    raise SystemExit
radius, _ = dataset_material(f"{a.results}/multistability/multistability.h5")  # the states' data set

fig = plt.figure(figsize=(12, 4.2))
grid = fig.add_gridspec(1, 5, width_ratios=[2.2, 1, 1, 1, 0.05])
ax = fig.add_subplot(grid[0, 0])
scale = float(s["energy_scale"])
for v in saddles:
    rows = [r for r in profile if int(r["state"]) == v["state"] and int(r["search"]) == v["search"]]
    e = np.array([float(r["energy"]) for r in rows])
    at = next(k for k, r in enumerate(rows) if r["saddle"] == "true")
    x = np.arange(len(e)) - at
    ax.plot(x, (e - e[0]) / scale, "-o", ms=2, lw=1, label=f"state {v['state']}, search {v['search']}")
    ax.plot([0], [(e[at] - e[0]) / scale], "v", color="tab:red", ms=6)
ax.axvline(0, color="0.8", lw=0.8)
ax.set_xlabel("image (0: the saddle; left: descent to the start, right: to the other minimum)")
ax.set_ylabel("(E - E_start) / (EI/L)")
ax.legend(fontsize=5, ncol=2, loc="lower left")
ax.set_title(f"4_1: {s['saddles']} verified saddles from {s['states']} states "
             f"({s['verified']} of {s['searches']} searches), {s['seconds_per_saddle']:.2g} s per saddle", fontsize=9)

top = max(saddles, key=lambda v: v["barrier"])
curves = [read_obj(f"{d}/{top['folder']}/{name}.obj") for name in ("start", "saddle", "end")]
frame = frame_of(curves[0])
vmax = max(np.percentile(curvature(P), 99) for P in curves)
lc = None
for c, (name, P) in enumerate(zip(("start", "saddle", "end"), curves)):
    sub = fig.add_subplot(grid[0, c + 1])
    lc = draw_framed(sub, P, "top", frame, radius=radius, vmax=vmax)
    moved = np.linalg.norm(P - curves[0], axis=1).max()
    sub.set_title(f"{name}\nmax. displacement {moved:.3g}", fontsize=8)
fig.colorbar(lc, cax=fig.add_subplot(grid[0, 4]), label="curvature")
fig.suptitle(f"highest barrier: {top['barrier_scaled']:.3g} EI/L (state {top['state']}, search {top['search']})",
             fontsize=9)
save(fig, a.out, "fig_saddles")
