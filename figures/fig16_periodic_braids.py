"""Fig. 16: relaxed periodic braids (σ1σ2⁻¹)^p and (σ1σ2⁻¹σ3)^p, two views
per member: from the side and along the symmetry axis, as tubes of the
wire's radius coloured by curvature. Each member is drawn at its p-fold
symmetric 3D state from the link scan (the coil relaxed at a prescribed link
under the slab and released, the most symmetric 3D state averaged over its p
periods and relaxed again at that link; summary.json "link_scan.symmetric"),
the paper's jumping-knot pipeline; a member without one is drawn at the
scan's 3D state nearest to its twist-free link, or, without a 3D state in
the scan, at its twist-free symmetric equilibrium (the flat coil), and
marked so. Viewed along the symmetry axis that the experiment found and measured
(ek::find_symmetry_axis)."""
import sys

import numpy as np

from common import curvature_colorbar, draw_curve, parse_args, plt, read_obj, read_summary, save, shared_vmax, \
    summary_radius

SCALE = 2.0  # wire drawn at this multiple of its radius
THREEDIM = 0.1  # kPlanarThreedim: a state at least this 3D is 3D
SYMMETRIC = 1e-6  # a p-fold symmetry error at most this is p-fold symmetric (PaperPeriodicBraids)

a = parse_args(__doc__)
s = read_summary(a.results, "periodic_braids")
members = s["members"]
if any(m.get("axis") is None for m in members):
    sys.exit("fig16_periodic_braids.py: periodic_braids/summary.json has no symmetry axis (written before it was "
             "recorded): rerun make experiment-periodic_braids")
radius = summary_radius(s, "periodic_braids")

def state(m):
    """(curve file, axis, label) of the state drawn for member m: its p-fold
    symmetric 3D state from the link scan; else the scan's 3D state nearest
    to the twist-free link Lk_0 (not p-fold symmetric), viewed along the
    coil's axis; else the twist-free symmetric equilibrium (the flat coil)."""
    scan = m.get("link_scan") or {}
    y = scan.get("symmetric")
    if y is not None and y["status"] == "converged-stable" and y["threedim"] >= THREEDIM \
            and y["symmetry_error"] <= SYMMETRIC:
        return y["curve"], y["axis"], f"Lk {y['link']:g}: symmetric ({y['symmetry_error']:.0e})"
    runs = [r for r in scan.get("runs", []) if r["three_d"] and r.get("curve")]
    if runs:
        r = min(runs, key=lambda r: (abs(r["link"] - scan["center"]), r["link"]))
        return r["curve"], m["axis"], f"Lk {r['link']:g}: asym. ({r['symmetry_error']:.2f})"
    return m["symmetric_curve"], m["axis"], "flat at every Lk"


drawn = [state(m) for m in members]
curves = [read_obj(f"{a.results}/periodic_braids/{c}") for c, _, _ in drawn]
vmax = shared_vmax(curves)
fig, axs = plt.subplots(2, len(members), figsize=(1.9 * len(members) + 0.5, 4.4), squeeze=False,
                        gridspec_kw={"hspace": 0.25, "wspace": 0.05})
sm = None
for col, (m, P, (_, axis, note)) in enumerate(zip(members, curves, drawn)):
    axis = np.array(axis, dtype=float)
    axis /= np.linalg.norm(axis)
    u = np.cross(axis, [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    # side: looking across the axis (axis up); along the axis: looking down it
    sm = draw_curve(axs[0][col], P, radius=radius, radius_scale=SCALE, view=(-u, axis), vmax=vmax)
    draw_curve(axs[1][col], P, radius=radius, radius_scale=SCALE, view=(-axis, u), vmax=vmax)
    word = "σ1σ2⁻¹" if m["family"] == "s1s2i" else "σ1σ2⁻¹σ3"
    axs[0][col].set_title(f"({word})^{m['p']}\n{m.get('knot') or ''}", fontsize=7)
    axs[1][col].set_xlabel(note, fontsize=6)
axs[0][0].set_ylabel("side", fontsize=8)
axs[1][0].set_ylabel("along the axis", fontsize=8)
curvature_colorbar(fig, sm, axs.ravel().tolist())
fig.suptitle(f"periodic braids relaxed at prescribed links Lk from the flat coil (wire drawn at {SCALE:g}× its radius "
             f"r = {radius:g}; colour: curvature)", fontsize=9)
save(fig, a.out, "fig16_periodic_braids")
