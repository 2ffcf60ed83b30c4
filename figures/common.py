"""Shared helpers of the figure scripts: arguments, reading results, drawing
curves (draw_curve: one view; draw_three_shadows: three orthogonal shadow
projections coloured by curvature, as the paper's figures do), saving PNG
and PDF. Figure scripts read only the
experiments' results files (results/<scale>/<experiment>/...), through the
readers here: read_summary (summary.json), read_csv with flag (CSV tables),
read_obj (curves), load_equilibria (data sets). The files' schemas are
documented in docs/results.md; thresholds come from the summaries (the
experiments write the values they applied)."""
import argparse
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402


def parse_args(description):
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--results", default="results/default", help="results folder of one scale")
    p.add_argument("--out", default="figures/out", help="output folder for PNG and PDF")
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    return a


def need(path):
    if not os.path.exists(path):
        sys.exit(f"{os.path.basename(sys.argv[0])}: missing {path}: run the experiment first (make experiment-...)")
    return path


def read_json(path):
    with open(need(path)) as f:
        return json.load(f)


def read_csv(path):
    with open(need(path)) as f:
        return list(csv.DictReader(f))


def read_summary(results, experiment):
    """results/<scale>/<experiment>/summary.json as a dict (docs/results.md)."""
    return read_json(os.path.join(results, experiment, "summary.json"))


def flag(cell):
    """A CSV flag cell: "true"/"false" ("1"/"0" in files written before typed
    results); an empty cell (or the old "-") is None."""
    if cell in ("true", "1"):
        return True
    if cell in ("false", "0"):
        return False
    if cell in ("", "-", None):
        return None
    raise ValueError(f"CSV flag {cell!r}: expected true, false or empty")


def read_obj(path):
    """The vertices of a curve file written by the experiments (OBJ "v x y z"
    lines), n by 3."""
    with open(need(path)) as f:
        return np.array([[float(x) for x in line.split()[1:4]] for line in f if line.startswith("v ")])


def save(fig, out, name):
    for ext in ("png", "pdf"):
        fig.savefig(os.path.join(out, f"{name}.{ext}"), dpi=150, bbox_inches="tight")
    plt.close(fig)
    print(f"wrote {os.path.join(out, name)}.png and .pdf")


def curvature(P):
    """Turning angle at each vertex divided by the Voronoi length (paper Section 7.1)."""
    e = np.roll(P, -1, axis=0) - P
    a, b = np.roll(e, 1, axis=0), e
    cross = np.linalg.norm(np.cross(a, b), axis=1)
    dot = np.sum(a * b, axis=1)
    angle = np.arctan2(cross, dot)
    vor = 0.5 * (np.linalg.norm(a, axis=1) + np.linalg.norm(b, axis=1))
    return angle / vor


def principal_frame(P):
    """Centres the curve and rotates it to its principal axes (largest first)."""
    Q = P - P.mean(axis=0)
    _, _, vt = np.linalg.svd(Q, full_matrices=False)
    return Q @ vt.T


def draw_shadow(ax, P, values, axes, vmax, lw=1.2):
    """Draws the projection of the closed curve P onto two axes, coloured by values."""
    pts = P[:, axes]
    seg = np.stack([pts, np.roll(pts, -1, axis=0)], axis=1)
    lc = LineCollection(seg, cmap="viridis", norm=plt.Normalize(0, vmax), linewidths=lw)
    lc.set_array(0.5 * (values + np.roll(values, -1)))
    ax.add_collection(lc)
    ax.set_aspect("equal")
    ax.autoscale()
    ax.set_xticks([])
    ax.set_yticks([])
    return lc


def frame_of(P):
    """The principal frame of a curve: (centre, R) with the rows of R its
    principal axes, largest first; apply_frame(P, frame) = (P - centre) @ R.T.
    Curves aligned onto one another (the search's alignment) are drawn in
    the frame of one of them, so that they overlay."""
    c = P.mean(axis=0)
    _, _, vt = np.linalg.svd(P - c, full_matrices=False)
    return c, vt


def apply_frame(P, frame):
    c, R = frame
    return (P - c) @ R.T


VIEWS = {"top": (0, 1), "front": (0, 2), "side": (1, 2)}


def draw_curve(ax, P, view="top", frame=None, color=None, vmax=None, lw=1.2, label=None):
    """Draws one closed curve (n by 3) into an axes, seen from `view` (top,
    front or side of `frame`, default the curve's own principal frame):
    coloured by curvature, or in one `color` (for overlays). The one function
    through which the figures draw a knot, so that another renderer can
    replace it; returns what a colour bar needs (or None)."""
    Q = apply_frame(P, frame or frame_of(P))
    axes = VIEWS[view]
    if color is not None:
        pts = Q[:, axes]
        closed = np.vstack([pts, pts[:1]])
        ax.plot(closed[:, 0], closed[:, 1], color=color, lw=lw, label=label)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        return None
    k = curvature(Q)
    return draw_shadow(ax, Q, k, axes, vmax or max(np.percentile(k, 99), 1e-9), lw=lw)


def draw_three_shadows(axs, P, vmax=None):
    """Three orthogonal shadows (xy, xz, yz of the principal frame), coloured by curvature."""
    Q = principal_frame(P)
    k = curvature(Q)
    vmax = vmax or max(np.percentile(k, 99), 1e-9)
    lc = None
    for ax, axes, label in zip(axs, ((0, 1), (0, 2), (1, 2)), ("top", "front", "side")):
        lc = draw_shadow(ax, Q, k, axes, vmax)
        ax.set_title(label, fontsize=7)
    return lc


def load_equilibria(h5_path, knot):
    import h5py

    with h5py.File(need(h5_path), "r") as f:
        g = f["knots"][knot]
        eq = np.array(g["equilibria"])
        names = [n.decode() if isinstance(n, bytes) else n for n in g["attribute_names"][:]]
        attrs = np.array(g["attributes"])
        sim = np.array(g["similarity"])
        link = np.array(g["linkage"])
    return eq, dict(zip(names, attrs.T)), sim, link


def draw_distinct_equilibria(a, knot, name):
    """The distinct equilibria (cluster representatives) of a knot of the
    multistability experiment, sorted by energy, as shadow triples."""
    eq, attrs, _, _ = load_equilibria(f"{a.results}/multistability/multistability.h5", knot)
    clusters = read_csv(f"{a.results}/multistability/clusters_{knot}.csv")[:16]
    cols = min(len(clusters), 8)
    rows = (len(clusters) + cols - 1) // cols
    fig, axs = plt.subplots(rows * 3, cols, figsize=(1.5 * cols, 4.2 * rows), squeeze=False)
    for c, row in enumerate(clusters):
        r, col = divmod(c, cols)
        draw_three_shadows([axs[3 * r + k][col] for k in range(3)], eq[int(row["representative"])])
        for k in range(3):
            axs[3 * r + k][col].set_title("")
        axs[3 * r][col].set_title(f"#{c + 1}  E = {float(row['energy']):.4f}\n3D-ness {float(row['threedim']):.2f}, "
                                  f"x{row['size']}", fontsize=6)
    for r in range(rows * 3):
        for col in range(cols):
            if not axs[r][col].has_data():
                axs[r][col].axis("off")
    for r in range(rows):
        for k, label in enumerate(("top", "front", "side")):
            axs[3 * r + k][0].set_ylabel(label, fontsize=7)
    fig.suptitle(f"{knot}: {len(clusters)} distinct equilibria by energy (colour: curvature)", fontsize=9)
    save(fig, a.out, name)
