"""Figs. 12 and 13: jumping knots. For a few knots that jump: the flat
multi-covered coil (relaxed under the planarity slab with the link of the 3D
target), the state it jumps to after the slab is released, from the top and
the front, and the energy released. Wires as shaded tubes of their radius
(scaled up, as the title says), coloured by curvature on one scale."""
from common import (curvature_colorbar, draw_curve, draw_views, flag, parse_args, plt, read_csv, read_obj,
                    read_summary, save, shared_vmax, summary_radius)

SCALE = 2.0  # wire drawn at this multiple of its radius

a = parse_args(__doc__)
rows = read_csv(f"{a.results}/jumping_knots/jumping.csv")
s = read_summary(a.results, "jumping_knots")
radius = summary_radius(s, "jumping_knots")
jumping = [r for r in rows if flag(r["jumps"])]
shown = sorted(jumping, key=lambda r: -float(r["energy_released"]))[:6] or rows[:1]

curves = [(read_obj(f"{a.results}/jumping_knots/curves/{r['knot']}_flat.obj"),
           read_obj(f"{a.results}/jumping_knots/curves/{r['knot']}_final.obj")) for r in shown]
vmax = shared_vmax([c for pair in curves for c in pair])
fig, axs = plt.subplots(3, len(shown), figsize=(2.1 * len(shown) + 0.5, 6.9), squeeze=False,
                        gridspec_kw={"height_ratios": [1.0, 1.0, 0.6], "hspace": 0.25, "wspace": 0.05})
sm = None
for col, (r, (flat, final)) in enumerate(zip(shown, curves)):
    draw_curve(axs[0][col], flat, radius=radius, radius_scale=SCALE, view="top", vmax=vmax)
    axs[0][col].set_title(f"{r['knot']}: flat coil\nE = {float(r['flat_energy']):.3f}, Lk = {float(r['link']):.2f}",
                          fontsize=7)
    sm = draw_views([axs[1][col], axs[2][col]], final, labels=False, radius=radius, radius_scale=SCALE, vmax=vmax)
    axs[1][col].set_title(f"after release: E = {float(r['final_energy']):.3f}\n3D-ness "
                          f"{float(r['final_threedim']):.2f} ({'jumps' if flag(r['jumps']) else 'no jump'})",
                          fontsize=7)
axs[0][0].set_ylabel("under the slab (top)", fontsize=7)
axs[1][0].set_ylabel("released (top)", fontsize=7)
axs[2][0].set_ylabel("released (front)", fontsize=7)
curvature_colorbar(fig, sm, axs.ravel().tolist())
fig.suptitle(f"jumping knots: {len(jumping)} of {s['tested']} knots tested jump "
             f"(wire drawn at {SCALE:g}× its radius r = {radius:g}; colour: curvature)", fontsize=9)
save(fig, a.out, "fig12_jumping_knots")
