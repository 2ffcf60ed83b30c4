"""Knots under load (beyond the paper; Section 8.5 names it future work).
Top: one panel per puzzle pair and load: the reaction of the device (the
plates' force, the pull's tension) against its control divided by the
control at the start (the gap or distance at which the start just touches
the device), one line per loaded state (from A, from B); a snap is marked by
a cross at the control where its branch ended, a flip (the released state
is the pair's other state) by a star, a branch jump (the path left its
branch without releasing energy: no snap) by a circle. Bottom: a
flip's state before it snapped, the state it fell into under the load, and
that state released, as tubes of the wire's radius in the first one's
principal frame, seen along its axis of least extent (a flip of a pair whose
barrier the transitions computed first; without a flip, the first snap's).
The plates' panels have a logarithmic control axis."""
import numpy as np
from matplotlib.ticker import NullFormatter

from common import draw_framed, frame_of, parse_args, plt, read_csv, read_obj, read_summary, save, save_empty


def number(cell):
    """A CSV number cell with 3 significant digits; an empty cell stays empty."""
    return f"{float(cell):.3g}" if cell else ""


a = parse_args(__doc__)
d = f"{a.results}/loads"
s = read_summary(a.results, "loads")
runs = read_csv(f"{d}/loads.csv")
snaps = read_csv(f"{d}/snaps.csv")
started = [r for r in runs if r["curve_start"]]  # a run that stalled at its start has no curve
if not started:
    save_empty(a.out, "fig_loads", "no puzzle pair loaded at this scale")
    raise SystemExit

# one panel per pair (knot and its two states) and load
panels = []
for r in runs:
    key = (r["knot"], *sorted((r["state_from"], r["state_to"]), key=int), r["load"])
    if key not in panels:
        panels.append(key)
cols = min(4, len(panels))
rows = (len(panels) + cols - 1) // cols
fig = plt.figure(figsize=(3.0 * max(cols, 3), 2.4 * rows + 3.0))
grid = fig.add_gridspec(rows + 1, cols, height_ratios=[1.0] * rows + [1.25], hspace=0.55, wspace=0.32)
for p, key in enumerate(panels):
    ax = fig.add_subplot(grid[p // cols, p % cols])
    for r in runs:
        if (r["knot"], *sorted((r["state_from"], r["state_to"]), key=int), r["load"]) != key:
            continue
        path = read_csv(f"{d}/paths/run_{r['run']}.csv")
        start = float(r["from"])
        mu = np.array([float(q["parameter"]) for q in path]) / start
        force = np.array([float(q["reaction"]) for q in path])
        line, = ax.plot(mu, force, "-", lw=0.9, label=f"from {r['state_from']} ({r['status']})")
        for q in path:
            if q["event"] == "branch-jump":
                ax.plot([float(q["parameter"]) / start], [float(q["reaction"])], "o", mfc="none",
                        color=line.get_color(), ms=4)
        for z in (z for z in snaps if z["run"] == r["run"]):
            flip = z["released_state"] == "other"
            ax.plot([float(z["parameter"]) / start], [float(z["reaction"])], "*" if flip else "x",
                    color=line.get_color(), ms=8 if flip else 4, mew=0.8)
    if key[3] == "plates":  # the gap closes over up to two decades: a log axis
        ax.set_xscale("log")
        ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_title(f"{key[0]} {key[1]}–{key[2]}: {key[3]}", fontsize=8)
    ax.tick_params(which="both", labelsize=6)
    ax.legend(fontsize=5.5, loc="best")
    if p % cols == 0:
        ax.set_ylabel("force [energy/length]", fontsize=7)
    ax.set_xlabel("control / control at the start", fontsize=7)

# a flip's states: the first flip of a pair whose barrier was computed, else
# the first flip, else the first snap
flips = [z for z in snaps if z["released_state"] == "other"]
joined = [z for z in flips if next(r for r in runs if r["run"] == z["run"])["barrier_scaled"]]
z = (joined or flips or snaps or [None])[0]
if z is not None:
    run = next(r for r in runs if r["run"] == z["run"])
    names = [(f"before (control {float(z['parameter']):.3g})", z["curve_before"]),
             ("fallen into, loaded", z["curve_loaded"]),
             (f"released: {z['released_state']}", z["curve_released"])]
    curves = [read_obj(f"{d}/{f}") for _, f in names]
    frame = frame_of(curves[0])
    bottom = grid[rows, :].subgridspec(1, len(curves), wspace=0.1)  # three tubes however few panels above
    for c, ((title, _), P) in enumerate(zip(names, curves)):
        sub = fig.add_subplot(bottom[0, c])
        draw_framed(sub, P, "top", frame, radius=float(s["radius"]))
        sub.set_title(title, fontsize=8)
    what = (f"flip of run {run['run']}: {run['knot']} {run['state_from']} → {run['state_to']} by {run['load']}, "
            f"force {number(z['reaction'])}, work {number(run['flip_work_scaled'])} EI/L against a computed barrier "
            f"{number(run['barrier_scaled']) or 'not joined'} EI/L") if flips else \
        f"first snap (run {run['run']}: {run['knot']} {run['state_from']} by {run['load']}); no flip at this scale"
    caption = fig.add_subplot(grid[rows, :])
    caption.axis("off")
    caption.text(0.5, 1.16, what, transform=caption.transAxes, ha="center", fontsize=8)
fig.suptitle(f"{s['runs']} runs on {s['pairs']} pairs: {s['snaps']} snaps (x), {s['flips']} flips (*), "
             f"branch jumps (o) are no snaps", fontsize=9)
save(fig, a.out, "fig_loads")
