"""Knots under load (beyond the paper; Section 8.5 names it future work):
(a) the reaction of each run's device against its control (the plates'
force against their gap, the pull's tension against its distance) along the
stable path, each snap marked by a cross at the control where its branch
ended, a flip (the released state is the pair's other state) by a star;
(b) the first run's relaxed start (of those that found one) and, when it snapped, the state before
its first snap and that snap's state released from the load, as tubes of
the wire's radius in the start's principal frame, seen along its axis of least extent."""
import numpy as np

from common import draw_framed, flag, frame_of, parse_args, plt, read_csv, read_obj, read_summary, save, save_empty



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

fig = plt.figure(figsize=(12, 4.4))
grid = fig.add_gridspec(1, 4, width_ratios=[2.2, 1, 1, 1])
ax = fig.add_subplot(grid[0, 0])
for r in runs:
    path = read_csv(f"{d}/paths/run_{r['run']}.csv")
    mu = np.array([float(p["parameter"]) for p in path])
    force = np.array([float(p["reaction"]) for p in path])
    line, = ax.plot(mu, force, "-", lw=1,
                    label=f"run {r['run']}: {r['knot']} {r['state_from']} by {r['load']} ({r['status']})")
    for z in (z for z in snaps if z["run"] == r["run"]):
        marker = "*" if z["released_state"] == "other" else "x"
        ax.plot([float(z["parameter"])], [float(z["reaction"])], marker, color=line.get_color(), ms=8)
ax.set_xlabel("control: plates' gap or pull's distance [length]")
ax.set_ylabel("reaction: force on the device [energy/length]")
ax.legend(fontsize=6, loc="best")
ax.set_title(f"{s['runs']} runs on {s['pairs']} pairs: {s['snaps']} snaps (x), {s['flips']} flips (*)", fontsize=9)

first = started[0]
names = [("relaxed start", first["curve_start"])]
first_snaps = [z for z in snaps if z["run"] == first["run"]]
if first_snaps:
    z = first_snaps[0]
    names += [(f"before snap 0 (control {float(z['parameter']):.3g})", z["curve_before"]),
              (f"released: {z['released_state']}", z["curve_released"])]
curves = [read_obj(f"{d}/{f}") for _, f in names]
frame = frame_of(curves[0])
for c, ((title, _), P) in enumerate(zip(names, curves)):
    sub = fig.add_subplot(grid[0, c + 1])
    draw_framed(sub, P, "top", frame, radius=float(s["radius"]))
    sub.set_title(title, fontsize=8)
flipped = flag(first["flip"])
fig.suptitle(f"run {first['run']}: {first['knot']} state {first['state_from']} by {first['load']}, "
             f"{'flips to state ' + first['state_to'] if flipped else 'no flip'}; "
             f"computed barrier {number(first['barrier_scaled']) or 'not joined'}"
             f"{', upper bound ' + number(first['upper_bound_scaled']) if first['upper_bound_scaled'] else ''} EI/L; "
             f"work done {number(first['work_scaled'])} EI/L", fontsize=9)
save(fig, a.out, "fig_loads")
