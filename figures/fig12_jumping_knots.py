"""Figs. 12 and 13: jumping knots. For a few knots that jump: the flat
multi-covered coil (relaxed under the planarity slab with the link of the 3D
target), the three orthogonal shadows of the state it jumps to after the slab
is released, and the energy released."""
import numpy as np

from common import (curvature, draw_shadow, draw_three_shadows, flag, parse_args, plt, read_csv, read_obj,
                    read_summary, save)

a = parse_args(__doc__)
rows = read_csv(f"{a.results}/jumping_knots/jumping.csv")
s = read_summary(a.results, "jumping_knots")
jumping = [r for r in rows if flag(r["jumps"])]
shown = sorted(jumping, key=lambda r: -float(r["energy_released"]))[:6] or rows[:1]


fig, axs = plt.subplots(4, len(shown), figsize=(2.0 * len(shown), 7.5), squeeze=False)
for col, r in enumerate(shown):
    flat = read_obj(f"{a.results}/jumping_knots/curves/{r['knot']}_flat.obj")
    final = read_obj(f"{a.results}/jumping_knots/curves/{r['knot']}_final.obj")
    Q = flat - flat.mean(axis=0)
    k = curvature(Q)
    draw_shadow(axs[0][col], Q, k, (0, 1), np.percentile(k, 99))
    axs[0][col].set_title(f"{r['knot']}: flat coil\nE = {float(r['flat_energy']):.3f}, Lk = {float(r['link']):.2f}",
                          fontsize=7)
    draw_three_shadows([axs[1][col], axs[2][col], axs[3][col]], final)
    axs[1][col].set_title(f"after release: E = {float(r['final_energy']):.3f}\n3D-ness "
                          f"{float(r['final_threedim']):.2f} ({'jumps' if flag(r['jumps']) else 'no jump'})",
                          fontsize=7)
fig.suptitle(f"jumping knots: {len(jumping)} of {s['tested']} knots tested jump", fontsize=10)
save(fig, a.out, "fig12_jumping_knots")
