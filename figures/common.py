"""Shared helpers of the figure scripts: arguments, reading results, drawing
curves, saving PNG and PDF. Figure scripts read only the experiments'
results files (results/<scale>/<experiment>/...), through the readers here:
read_summary (summary.json), read_csv with flag (CSV tables), read_obj
(curves), read_link (links), load_equilibria and dataset_material (data sets). The files'
schemas are documented in docs/results.md; thresholds and the wire radius
come from the results (the experiments write the values they applied).

Curves are drawn by draw_curve(ax, P, radius=..., view=..., color=...)
(figures/render.py): the wire as a shaded tube of its radius, rendered by
POV-Ray, with over/under crossings hidden as in a photograph; draw_views()
draws one curve in several views. save() waits for the renders."""
import argparse
import csv
import json
import os
import sys

import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import render  # noqa: E402
from render import contact_legend, curvature, draw_curve  # noqa: E402,F401

_started = time.perf_counter()


def parse_args(description):
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--results", default="results/default", help="results folder of one scale")
    p.add_argument("--out", default="figures/out", help="output folder for PNG and PDF")
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    render.cache_dir = os.path.join(a.out, ".render-cache")
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
    """A CSV flag cell: "true"/"false"; an empty cell is None."""
    if cell == "true":
        return True
    if cell == "false":
        return False
    if cell in ("", None):
        return None
    raise ValueError(f"CSV flag {cell!r}: expected true, false or empty")


def read_obj(path):
    """The vertices of a curve file written by the experiments (OBJ "v x y z"
    lines), n by 3."""
    with open(need(path)) as f:
        return np.array([[float(x) for x in line.split()[1:4]] for line in f if line.startswith("v ")])


def read_link(path):
    """The components of a link file written by the experiments (OBJ "v" lines
    and one closed "l" loop per component, docs/cli.md "Curve files"): a list
    of n_c by 3 arrays, in the order of their first vertices."""
    with open(need(path)) as f:
        lines = f.read().splitlines()
    vertices = np.array([[float(x) for x in line.split()[1:4]] for line in lines if line.startswith("v ")])
    nxt = {}
    for line in lines:
        if line.startswith("l "):
            idx = [int(t) - 1 for t in line.split()[1:]]
            for i, j in zip(idx[:-1], idx[1:]):
                nxt.setdefault(i, j)
    components, seen = [], set()
    for start in range(len(vertices)):
        if start in seen:
            continue
        loop, v = [], start
        while v not in seen:
            seen.add(v)
            loop.append(v)
            v = nxt.get(v, start)
        components.append(vertices[loop])
    return components


def save(fig, out, name):
    render.finish()
    for ext in ("png", "pdf"):
        fig.savefig(os.path.join(out, f"{name}.{ext}"), dpi=150, bbox_inches="tight")
    plt.close(fig)
    s = render.stats
    print(f"wrote {os.path.join(out, name)}.png and .pdf in {time.perf_counter() - _started:.1f} s "
          f"({s['renders']} tube renders, {s['seconds']:.1f} s of POV-Ray runs; {s['cached']} from the cache)")


def draw_views(axs, P, views=("top", "front"), labels=True, **kwargs):
    """One curve in several views (draw_curve's keyword arguments, radius
    among them), one axes each; returns the last ScalarMappable."""
    sm = None
    for ax, view in zip(axs, views):
        sm = draw_curve(ax, P, view=view, **kwargs)
        if labels and isinstance(view, str):
            ax.set_title(view, fontsize=7)
    return sm


def frame_of(P):
    """The principal frame of a curve: (centre, R) with the rows of R its
    principal axes, largest first. Curves aligned onto one another (the
    search's alignment) are drawn in the frame of one of them
    (draw_framed), so that they overlay."""
    c = P.mean(axis=0)
    _, _, vt = np.linalg.svd(P - c, full_matrices=False)
    return c, vt


def draw_framed(ax, P, view, frame, *, radius, color="curvature", label=None, radius_scale=4.0, **kwargs):
    """draw_curve seen from `view` (top, front or side) of `frame` instead of
    the curve's own principal frame; several curves drawn into one axes this
    way overlay (each a tube; the later one is drawn over the earlier). The
    axes' limits cover every curve drawn into it; `label` adds a legend entry
    in `color`."""
    c, R = frame if frame is not None else frame_of(np.asarray(P, dtype=float))
    i, j = {"top": (0, 1), "front": (0, 2), "side": (1, 2)}[view]
    right, up = R[i], R[j]
    toward = np.cross(right, up)
    sm = draw_curve(ax, np.asarray(P, dtype=float) - c, radius=radius, radius_scale=radius_scale,
                    view=(-toward, up), color=color, center=False, **kwargs)
    extents = [im.get_extent() for im in ax.images]
    ax.set_xlim(min(e[0] for e in extents), max(e[1] for e in extents))
    ax.set_ylim(min(e[2] for e in extents), max(e[3] for e in extents))
    if label is not None:
        ax.plot([], [], color=color, lw=3, label=label)
    return sm


def save_empty(out, name, text):
    """The figure when its results hold nothing to draw: one line saying so."""
    fig, ax = plt.subplots(figsize=(4, 1))
    ax.text(0.5, 0.5, text, ha="center")
    ax.axis("off")
    save(fig, out, name)


def dataset_material(h5_path):
    """(radius, dhat) of a data set: the wire radius and the contact distance [length]."""
    import h5py

    with h5py.File(need(h5_path), "r") as f:
        return float(f.attrs["radius"]), float(f.attrs["dhat"])


def summary_radius(summary, experiment):
    """The wire radius a summary records (its key "radius")."""
    return float(summary["radius"])


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


def shared_vmax(curves):
    """Top of a curvature colour scale shared by several curves: the 99th
    percentile of all their vertices' curvatures."""
    return max(float(np.percentile(np.concatenate([curvature(P) for P in curves]), 99)), 1e-9)


def curvature_colorbar(fig, sm, axs, label="curvature [1/length]"):
    cb = fig.colorbar(sm, ax=axs, fraction=0.02, pad=0.01, shrink=0.8)
    cb.set_label(label, fontsize=7)
    cb.ax.tick_params(labelsize=6)
    return cb


def draw_distinct_equilibria(a, knot, name, radius_scale=4.0):
    """The distinct equilibria (cluster representatives) of a knot of the
    multistability experiment, sorted by energy: each as a tube from the top
    (along its smallest principal axis) and, smaller, from the front,
    coloured by curvature on one shared scale."""
    h5 = f"{a.results}/multistability/multistability.h5"
    eq, attrs, _, _ = load_equilibria(h5, knot)
    radius, _ = dataset_material(h5)
    clusters = read_csv(f"{a.results}/multistability/clusters_{knot}.csv")[:16]
    cols = min(len(clusters), 8)
    rows = (len(clusters) + cols - 1) // cols
    curves = [eq[int(row["representative"])] for row in clusters]
    vmax = shared_vmax(curves)
    fig = plt.figure(figsize=(1.75 * cols + 0.6, 2.75 * rows + 0.4))
    grid = fig.add_gridspec(2 * rows, cols, height_ratios=[1.0, 0.55] * rows, hspace=0.12, wspace=0.05)
    axes, sm = [], None
    for c, (row, P) in enumerate(zip(clusters, curves)):
        r, col = divmod(c, cols)
        top, front = fig.add_subplot(grid[2 * r, col]), fig.add_subplot(grid[2 * r + 1, col])
        sm = draw_views([top, front], P, labels=False, radius=radius, radius_scale=radius_scale, vmax=vmax)
        top.set_title(f"#{c + 1}  E = {float(row['energy']):.4f}\n3D-ness {float(row['threedim']):.2f}, "
                      f"x{row['size']}", fontsize=6)
        axes += [top, front]
    if sm is not None:
        curvature_colorbar(fig, sm, axes)
    fig.suptitle(f"{knot}: {len(clusters)} distinct equilibria by energy, each from the top and the front "
                 f"(wire drawn at {radius_scale:g}× its radius r = {radius:g}; colour: curvature)", fontsize=8)
    save(fig, a.out, name)
