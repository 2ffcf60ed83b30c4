"""Jumping knots in time (beyond the paper's static release): top row, the
frictionless release of the figure knot (12a_1019) at six times, from the
flat coil to rest, as shaded tubes; bottom left, its 3D-ness and kinetic
energy over time at every friction coefficient of the grid; bottom right,
each knot's outcome against the friction coefficient μ (jumped, rests flat,
between, still moving at the end) with its bracket. Reads exp_jumping_dynamics' results only."""
import os

from common import draw_curve, parse_args, plt, read_csv, read_obj, read_summary, save, shared_vmax

SCALE = 2.0  # wire drawn at this multiple of its radius
SNAPSHOTS = 6

a = parse_args(__doc__)
d = f"{a.results}/jumping_dynamics"
s = read_summary(a.results, "jumping_dynamics")
rows = read_csv(f"{d}/dynamics.csv")
knot = s["figure_knot"]
frame_dir = f"{d}/frames/{knot}"
frames = sorted(f for f in os.listdir(frame_dir) if f.endswith(".obj"))
zero = [r for r in rows if r["knot"] == knot and float(r["mu"]) == 0.0 and float(r["time_step"]) == s["time_step"]]
traj0 = read_csv(f"{d}/{zero[0]['trajectory']}")
picks = [round(k * (len(frames) - 1) / (SNAPSHOTS - 1)) for k in range(SNAPSHOTS)]
curves = [read_obj(f"{frame_dir}/{frames[k]}") for k in picks]
vmax = shared_vmax(curves)

fig = plt.figure(figsize=(12.5, 6.6))
grid = fig.add_gridspec(2, SNAPSHOTS, height_ratios=[1.0, 1.05], hspace=0.35, wspace=0.08)
for col, (k, P) in enumerate(zip(picks, curves)):
    ax = fig.add_subplot(grid[0, col])
    draw_curve(ax, P, radius=s["radius"], radius_scale=SCALE, view="front", vmax=vmax)
    t = float(traj0[k]["time"])
    ax.set_title(f"t = {t:.0f}\n3D-ness {float(traj0[k]['threedim']):.2f}", fontsize=7)

ax = fig.add_subplot(grid[1, : SNAPSHOTS // 2])
ax2 = ax.twinx()
for r in rows:
    if r["knot"] != knot or float(r["time_step"]) != s["time_step"]:
        continue
    mu = float(r["mu"])
    tr = read_csv(f"{d}/{r['trajectory']}")
    t = [float(x["time"]) for x in tr]
    line, = ax.plot(t, [float(x["threedim"]) for x in tr], lw=1.2, label=f"μ = {mu:g} ({r['outcome']})")
    if mu == 0.0:
        ax2.plot(t, [float(x["kinetic"]) for x in tr], lw=0.8, ls=":", color=line.get_color())
ax.axhline(s["threedim_threshold"], color="0.5", lw=0.6, ls="--")
ax.axhline(s["planar_threshold"], color="0.7", lw=0.6, ls="--")
ax.set_xlabel("time")
ax.set_ylabel("3D-ness")
ax2.set_ylabel("kinetic energy at μ = 0 (dotted)")
ax.legend(fontsize=6, loc="center right")
ax.set_title(f"{knot}: 3D-ness over time (dashed: jumped ≥ {s['threedim_threshold']:g}, "
             f"flat < {s['planar_threshold']:g})", fontsize=8)

ax = fig.add_subplot(grid[1, SNAPSHOTS // 2 + 1:])
marks = {"jumped": ("^", "tab:red"), "flat": ("o", "tab:blue"), "between": ("s", "tab:orange"),
         "moving": ("x", "0.4")}
knots = s["knots"]
for r in rows:
    if float(r["time_step"]) != s["time_step"]:
        continue
    m, c = marks[r["outcome"]]
    ax.scatter(float(r["mu"]), knots.index(r["knot"]), marker=m, color=c, s=28, zorder=3)
for b in s["brackets"]:
    if b["mu_jumps"] is not None and b["mu_flat"] is not None:
        y = knots.index(b["knot"])
        ax.plot([b["mu_jumps"], b["mu_flat"]], [y, y], color="0.4", lw=3, alpha=0.35)
for name, (m, c) in marks.items():
    ax.scatter([], [], marker=m, color=c, label=name)
ax.set_yticks(range(len(knots)))
ax.set_yticklabels(knots, fontsize=7)
ax.set_xlabel("friction coefficient μ")
ax.legend(fontsize=6, loc="lower right")
ax.set_title("outcome of the release (grey: the bracket of the critical μ)", fontsize=8)
check = s.get("step_check")
note = (f"; at h/2 its frictionless end has similarity {check['similarity']:.3f} to the end at h" if check else "")
fig.suptitle(f"jumping knots in time: backward Euler, h = {s['time_step']:g}, air drag γ = {s['damping']:g}, "
             f"Coulomb friction μ between touching wires{note} (wire at {SCALE:g}× its radius)", fontsize=9)
save(fig, a.out, "fig_jumping_dynamics")
