"""Fig. 16: relaxed periodic braids (σ1σ2⁻¹)^p and (σ1σ2⁻¹σ3)^p, two views
per member: from the side and along the symmetry axis, coloured by curvature.
Each member is drawn at its p-fold symmetric equilibrium (the relaxed
state's p-fold average relaxed again, <curve>_symmetric.obj) when the
experiment wrote it, as the paper's Fig. 16 shows symmetric states."""
import os

import numpy as np

from common import curvature, draw_shadow, parse_args, plt, read_csv, save

a = parse_args(__doc__)
rows = read_csv(f"{a.results}/periodic_braids/periodic.csv")


def read_obj(path):
    return np.array([[float(x) for x in line.split()[1:4]] for line in open(path) if line.startswith("v ")])


fig, axs = plt.subplots(2, len(rows), figsize=(1.9 * len(rows), 4.2), squeeze=False)
for col, r in enumerate(rows):
    path = f"{a.results}/periodic_braids/{r['curve']}"
    symmetric = path[:-4] + "_symmetric.obj"
    P = read_obj(symmetric if os.path.exists(symmetric) else path)
    Q = P - P.mean(axis=0)
    w, v = np.linalg.eigh(Q.T @ Q)
    # the symmetry axis: the principal axis whose eigenvalue differs most from the other two
    gaps = [abs(w[k] - np.mean(np.delete(w, k))) for k in range(3)]
    axis = v[:, int(np.argmax(gaps))]
    u = np.cross(axis, [1.0, 0.0, 0.0] if abs(axis[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    t = np.cross(axis, u)
    R = Q @ np.stack([u, t, axis], axis=1)
    k = curvature(R)
    vmax = np.percentile(k, 99)
    draw_shadow(axs[0][col], R, k, (0, 2), vmax)
    draw_shadow(axs[1][col], R, k, (0, 1), vmax)
    name = r["knot"] if r["knot"] != "-" else ""
    word = "σ1σ2⁻¹" if r["family"] == "s1s2i" else "σ1σ2⁻¹σ3"
    axs[0][col].set_title(f"({word})^{r['p']}\n{name}", fontsize=7)
axs[0][0].set_ylabel("side", fontsize=8)
axs[1][0].set_ylabel("along the axis", fontsize=8)
save(fig, a.out, "fig16_periodic_braids")
