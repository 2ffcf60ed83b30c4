"""Fig. 16: periodic braids (σ1σ2⁻¹)^p and (σ1σ2⁻¹σ3)^p, each member in the
paper's two views (from the side and along the symmetry axis), as tubes of
the wire's radius coloured by curvature. Top two rows: the member's p-fold
symmetric 3D state: its symmetric critical point where that is 3D, labelled
with its Morse index (index 0: stable); where the symmetric critical point
is the flat coil, the restricted flow's 3D bottleneck (summary.json
"three_d_search"), labelled "not critical" with its gradient norm. Bottom
two rows: the equilibrium the relaxation from the paper's start (the braid
on a cylinder) reaches. Viewed along the symmetry axis of the symmetric
subspace (the cylinder's axis)."""
import numpy as np

from common import curvature_colorbar, draw_curve, parse_args, plt, read_obj, read_summary, save, shared_vmax, \
    summary_radius

SCALE = 2.0  # wire drawn at this multiple of its radius

a = parse_args(__doc__)
s = read_summary(a.results, "periodic_braids")
members = s["members"]
radius = summary_radius(s, "periodic_braids")
threshold = s["threedim_threshold"]


def symmetric_state(m):
    """(curve, label) of the member's p-fold symmetric 3D state."""
    c = m["symmetric_critical_point"]
    if c["threedim"] >= threshold:
        word = "stable" if c["index"] == 0 else "unstable"
        return c["curve"], f"critical, index {c['index']}: {word}"
    b = m["three_d_search"]
    return b["curve"], f"not critical: |∇E| = {b['gradient_norm']:.1e}"


def equilibrium(m):
    e = m["equilibrium"]
    return e["curve"], f"equilibrium: 3D-ness {e['threedim']:.2f}"


def axes_of(m):
    axis = np.array(m["symmetric_critical_point"]["axis"], dtype=float)
    axis /= np.linalg.norm(axis)
    u = np.cross(axis, [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 1.0, 0.0])
    return axis, u / np.linalg.norm(u)


rows = [[symmetric_state(m) for m in members], [equilibrium(m) for m in members]]
curves = [[read_obj(f"{a.results}/periodic_braids/{c}") for c, _ in row] for row in rows]
vmax = shared_vmax([P for row in curves for P in row])
fig, axs = plt.subplots(4, len(members), figsize=(1.9 * len(members) + 0.5, 8.6), squeeze=False,
                        gridspec_kw={"hspace": 0.3, "wspace": 0.05})
sm = None
for col, m in enumerate(members):
    axis, u = axes_of(m)
    for r in range(2):
        P, (_, note) = curves[r][col], rows[r][col]
        # side: looking across the axis (axis up); along the axis: looking down it
        sm = draw_curve(axs[2 * r][col], P, radius=radius, radius_scale=SCALE, view=(-u, axis), vmax=vmax)
        draw_curve(axs[2 * r + 1][col], P, radius=radius, radius_scale=SCALE, view=(-axis, u), vmax=vmax)
        axs[2 * r + 1][col].set_xlabel(note, fontsize=6)
    word = "σ1σ2⁻¹" if m["family"] == "s1s2i" else "σ1σ2⁻¹σ3"
    axs[0][col].set_title(f"({word})^{m['p']}\n{m.get('knot') or ''}", fontsize=7)
for r, name in enumerate(("symmetric state", "equilibrium")):
    axs[2 * r][0].set_ylabel(f"{name}\nside", fontsize=8)
    axs[2 * r + 1][0].set_ylabel("along the axis", fontsize=8)
curvature_colorbar(fig, sm, axs.ravel().tolist())
fig.suptitle("periodic braids: the p-fold symmetric 3D state (top) and the equilibrium reached from the paper's "
             f"start, the braid on a cylinder (bottom); wire drawn at {SCALE:g}× its radius r = {radius:g}; "
             "colour: curvature", fontsize=9)
save(fig, a.out, "fig16_periodic_braids")
