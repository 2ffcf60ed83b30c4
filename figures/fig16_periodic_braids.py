"""Fig. 16: relaxed periodic braids (σ1σ2⁻¹)^p and (σ1σ2⁻¹σ3)^p, two views
per member: from the side and along the symmetry axis, coloured by curvature.
Each member is drawn at its p-fold symmetric equilibrium (the relaxed
state's p-fold average relaxed again), as the paper's Fig. 16 shows
symmetric states, and viewed along the symmetry axis that the experiment
found and measured (summary.json "axis", ek::find_symmetry_axis)."""
import sys

import numpy as np

from common import curvature, draw_shadow, parse_args, plt, read_obj, read_summary, save

a = parse_args(__doc__)
members = read_summary(a.results, "periodic_braids")["members"]
if any(m.get("axis") is None for m in members):
    sys.exit("fig16_periodic_braids.py: periodic_braids/summary.json has no symmetry axis (written before it was "
             "recorded): rerun make experiment-periodic_braids")

fig, axs = plt.subplots(2, len(members), figsize=(1.9 * len(members), 4.2), squeeze=False)
for col, m in enumerate(members):
    P = read_obj(f"{a.results}/periodic_braids/{m['symmetric_curve']}")
    Q = P - P.mean(axis=0)
    axis = np.array(m["axis"], dtype=float)
    axis /= np.linalg.norm(axis)
    u = np.cross(axis, [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    t = np.cross(axis, u)
    R = Q @ np.stack([u, t, axis], axis=1)  # columns: two directions across the axis, then the axis
    k = curvature(R)
    vmax = np.percentile(k, 99)
    draw_shadow(axs[0][col], R, k, (0, 2), vmax)
    draw_shadow(axs[1][col], R, k, (0, 1), vmax)
    word = "σ1σ2⁻¹" if m["family"] == "s1s2i" else "σ1σ2⁻¹σ3"
    axs[0][col].set_title(f"({word})^{m['p']}\n{m.get('knot') or ''}", fontsize=7)
    axs[1][col].set_xlabel(f"symmetry error {m['symmetric']['symmetry_error']:.1e}", fontsize=6)
axs[0][0].set_ylabel("side", fontsize=8)
axs[1][0].set_ylabel("along the axis", fontsize=8)
save(fig, a.out, "fig16_periodic_braids")
