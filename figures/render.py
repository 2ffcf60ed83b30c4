"""Renders a closed curve as a shaded tube (the wire at its radius) with
POV-Ray, the ray tracer KnotPlot exports to, and places the image in a
matplotlib axes in the curve's own length units, so the figure scripts keep
composing every figure with matplotlib.

    draw_curve(ax, P, radius=0.2, view="top", color="curvature")

P is n by 3 (a closed polygon: the last vertex joins the first). The wire is
one cylinder per edge and one sphere per vertex, of radius `radius` times
`radius_scale`, lit by two lights with specular highlights, seen by an
orthographic camera, so a strand that passes over another hides it as in a
photograph of the wire. Colours: by curvature (turning angle over Voronoi
length, viridis, 0 .. vmax), by contact (edges closer than `dhat` to an edge
that shares no vertex with them, red, the others grey), one fixed colour, or
per-vertex values.

Views: "top" looks along the curve's smallest principal axis (the normal of
its best-fitting plane), "front" along the middle one, "side" along the
largest; or a pair (direction, up) of 3-vectors, the viewing direction
pointing from the viewer into the scene.

draw_curve() places a blank image of the right size at once and starts
POV-Ray in a worker thread; finish() (called by common.save) waits for the
renders and fills the images in, so the renders of a figure run together.
Renders are cached by content: the key hashes the camera-frame coordinates,
the radius, the colours, the image size and RENDER_VERSION, so a figure
redrawn from the same results reuses its images. The cache folder is
cache_dir (set by common.parse_args to <out>/.render-cache).
"""
import concurrent.futures
import hashlib
import os
import shutil
import subprocess
import tempfile
import threading
import time

import matplotlib
import matplotlib.pyplot as plt
import numpy as np

RENDER_VERSION = "tube-1"
cache_dir = None  # folder of cached renders; None: no cache
stats = {"renders": 0, "cached": 0, "seconds": 0.0}
WORKERS = 6  # concurrent POV-Ray runs (each traces on one thread)
_pool = None
_pending = []  # (AxesImage, future of its image), filled by finish()
_lock = threading.Lock()

GREY = (0.72, 0.72, 0.74)
CONTACT_RED = (0.85, 0.12, 0.10)


def povray_path():
    path = shutil.which("povray")
    if path is None:
        raise SystemExit("figures: POV-Ray is missing (Debian package povray): run make deps")
    return path


# ---- per-vertex quantities ----------------------------------------------------

def curvature(P):
    """Turning angle at each vertex divided by the Voronoi length (paper Section 7.1), length n."""
    e = np.roll(P, -1, axis=0) - P
    a, b = np.roll(e, 1, axis=0), e
    cross = np.linalg.norm(np.cross(a, b), axis=1)
    dot = np.sum(a * b, axis=1)
    angle = np.arctan2(cross, dot)
    vor = 0.5 * (np.linalg.norm(a, axis=1) + np.linalg.norm(b, axis=1))
    return angle / vor


def segment_distances(P, rows=None):
    """Distances between the edges of the closed polygon P (edge i joins
    vertex i to i+1): an r by n matrix for the edges `rows` (default all)
    against every edge, by the clamped closest-point formula of two segments
    (parallel segments handled). Edges sharing a vertex are set to inf."""
    n = len(P)
    rows = np.arange(n) if rows is None else np.asarray(rows)
    A0, A1 = P[rows], np.roll(P, -1, axis=0)[rows]
    B0, B1 = P, np.roll(P, -1, axis=0)
    d1 = (A1 - A0)[:, None, :]
    d2 = (B1 - B0)[None, :, :]
    r = A0[:, None, :] - B0[None, :, :]
    a = np.sum(d1 * d1, axis=2)
    e = np.sum(d2 * d2, axis=2)
    b = np.sum(d1 * d2, axis=2)
    c = np.sum(d1 * r, axis=2)
    f = np.sum(d2 * r, axis=2)
    denom = a * e - b * b
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.where(denom > 1e-12 * a * e, np.clip((b * f - c * e) / denom, 0.0, 1.0), 0.0)
        t = (b * s + f) / e
        t_clamped = np.clip(t, 0.0, 1.0)
        s = np.where(t != t_clamped, np.clip((b * t_clamped - c) / a, 0.0, 1.0), s)
    t = t_clamped
    diff = r + s[..., None] * d1 - t[..., None] * d2
    dist = np.linalg.norm(diff, axis=2)
    gap = np.abs(rows[:, None] - np.arange(n)[None, :])
    gap = np.minimum(gap, n - gap)
    dist[gap <= 1] = np.inf
    return dist


def contact_edges(P, dhat):
    """Boolean length-n array: edge i is closer than dhat to an edge that shares
    no vertex with it (an active contact pair of the barrier, paper Section 6)."""
    n = len(P)
    out = np.zeros(n, dtype=bool)
    for start in range(0, n, 256):  # blocks keep the r x n x 3 temporaries small
        rows = np.arange(start, min(n, start + 256))
        out[rows] = segment_distances(P, rows).min(axis=1) < dhat
    return out


# ---- camera ---------------------------------------------------------------------

def principal_axes(P):
    """Rows: the principal axes of the vertices, largest spread first."""
    Q = P - P.mean(axis=0)
    _, _, vt = np.linalg.svd(Q, full_matrices=False)
    return vt


def view_rotation(P, view):
    """3 by 3 rotation whose rows are the image's right, up and towards-viewer directions."""
    if isinstance(view, str):
        ax = principal_axes(P)
        right, up, toward = {"top": (ax[0], ax[1], ax[2]), "front": (ax[0], ax[2], ax[1]),
                             "side": (ax[1], ax[2], ax[0])}[view]
        toward = np.cross(right, up)  # right-handed: right x up = towards the viewer
        return np.stack([right, up, toward])
    direction, up = (np.asarray(v, dtype=float) for v in view)
    toward = -direction / np.linalg.norm(direction)
    up = up - np.dot(up, toward) * toward
    if np.linalg.norm(up) < 1e-9:
        raise ValueError("draw_curve: the up vector is parallel to the viewing direction")
    up /= np.linalg.norm(up)
    return np.stack([np.cross(up, toward), up, toward])


# ---- colours --------------------------------------------------------------------

def vertex_colors(P, color, cmap, vmax, dhat):
    """(n by 3 RGB in [0, 1], a ScalarMappable for a colour bar or None)."""
    n = len(P)
    if isinstance(color, str) and color == "curvature":
        k = curvature(P)
        vmax = vmax or max(float(np.percentile(k, 99)), 1e-9)
        sm = plt.cm.ScalarMappable(norm=plt.Normalize(0.0, vmax), cmap=cmap)
        return sm.to_rgba(k)[:, :3], sm
    if isinstance(color, str) and color == "contact":
        if dhat is None:
            raise ValueError("draw_curve: color='contact' needs dhat")
        edges = contact_edges(P, dhat)
        on = edges | np.roll(edges, 1)  # a vertex of an edge in contact
        rgb = np.where(on[:, None], np.array(CONTACT_RED), np.array(GREY))
        return rgb, None
    if isinstance(color, str):  # a matplotlib colour name, "#rrggbb" or a grey level "0.8"
        return np.array(np.broadcast_to(np.asarray(matplotlib.colors.to_rgb(color)), (n, 3))), None
    values = np.asarray(color, dtype=float)
    if values.shape == (n,):
        vmax = vmax if vmax is not None else float(values.max())
        sm = plt.cm.ScalarMappable(norm=plt.Normalize(float(values.min()), vmax), cmap=cmap)
        return sm.to_rgba(values)[:, :3], sm
    rgb = np.broadcast_to(np.asarray(matplotlib.colors.to_rgb(color)), (n, 3))
    return np.array(rgb), None


# ---- the scene ------------------------------------------------------------------

def scene(C, rho, rgb, extent, starts=None):
    """POV-Ray scene text: camera-frame points C (n by 3: right, up, towards
    the viewer), tube radius rho, vertex colours rgb, image extent
    (umin, umax, vmin, vmax). POV-Ray is left-handed (z into the screen), so
    z = -w. starts: the first vertex of each closed component (a link: the
    components back to back); None: one closed curve."""
    umin, umax, vmin, vmax = extent
    cu, cv = 0.5 * (umin + umax), 0.5 * (vmin + vmax)
    depth = float(np.abs(C[:, 2]).max()) + 10.0 * rho + 1.0
    lines = [
        "#version 3.7;",
        "global_settings { assumed_gamma 1.0 ambient_light rgb 1 }",
        f"camera {{ orthographic location <{cu:.6f}, {cv:.6f}, {-depth:.6f}> direction <0, 0, 1> "
        f"right <{umax - umin:.6f}, 0, 0> up <0, {vmax - vmin:.6f}, 0> }}",
        f"light_source {{ <{cu - 2 * depth:.3f}, {cv + 3 * depth:.3f}, {-4 * depth:.3f}> color rgb 0.85 parallel "
        f"point_at <{cu:.3f}, {cv:.3f}, 0> }}",
        f"light_source {{ <{cu + 3 * depth:.3f}, {cv - depth:.3f}, {-2 * depth:.3f}> color rgb 0.35 parallel "
        f"point_at <{cu:.3f}, {cv:.3f}, 0> shadowless }}",
        "#declare F = finish { ambient 0.16 diffuse 0.75 specular 0.45 roughness 0.02 }",
        "union {",
    ]
    n = len(C)
    bounds = list(starts or [0]) + [n]
    nxt = np.empty(n, dtype=int)  # the next vertex within each closed component
    for a, b in zip(bounds[:-1], bounds[1:]):
        nxt[a:b] = np.roll(np.arange(a, b), -1)
    pts = [f"<{c[0]:.6f}, {c[1]:.6f}, {-c[2]:.6f}>" for c in C]
    col = [f"srgb <{r:.4f}, {g:.4f}, {b:.4f}>" for r, g, b in rgb]
    edge_rgb = 0.5 * (rgb + rgb[nxt])
    for i in range(n):
        j = nxt[i]
        r, g, b = edge_rgb[i]
        lines.append(f"cylinder {{ {pts[i]}, {pts[j]}, {rho:.6f} open "
                     f"texture {{ pigment {{ srgb <{r:.4f}, {g:.4f}, {b:.4f}> }} finish {{ F }} }} }}")
        lines.append(f"sphere {{ {pts[i]}, {rho:.6f} texture {{ pigment {{ {col[i]} }} finish {{ F }} }} }}")
    lines.append("}")
    return "\n".join(lines) + "\n"


def cache_key(C, rho, rgb, extent, width, height, starts=None):
    key = hashlib.sha256()
    for part in (RENDER_VERSION.encode(), np.ascontiguousarray(C, dtype=np.float64).tobytes(),
                 np.float64(rho).tobytes(), np.ascontiguousarray(rgb, dtype=np.float64).tobytes(),
                 np.asarray(extent, dtype=np.float64).tobytes(), f"{width}x{height}".encode(),
                 (b"" if starts is None else np.asarray(starts, dtype=np.int64).tobytes())):
        key.update(part)
    return key.hexdigest()[:32]


def run_povray(text, width, height, cached):
    """Renders the scene text to a PNG (cached: its path in the cache, or None)
    and returns the RGBA image. Runs in a worker thread."""
    t0 = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="ek-render-") as tmp:
        pov, png = os.path.join(tmp, "scene.pov"), os.path.join(tmp, "scene.png")
        with open(pov, "w") as f:
            f.write(text)
        cmd = [povray_path(), "-D", "-V", "+WT1", "+UA", "+FN", "+A0.1", "+AM2", "+R2", f"+W{width}", f"+H{height}",
               f"+I{pov}", f"+O{png}"]
        done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        if done.returncode != 0 or not os.path.exists(png):
            tail = (done.stderr or "").strip().splitlines()[-3:]
            raise RuntimeError("POV-Ray failed: " + " | ".join(tail))
        image = plt.imread(png)
        if cached:
            os.makedirs(os.path.dirname(cached), exist_ok=True)
            shutil.copyfile(png, cached + ".tmp")
            os.replace(cached + ".tmp", cached)
    with _lock:
        stats["renders"] += 1
        stats["seconds"] += time.perf_counter() - t0
    return image


def render_async(C, rho, rgb, extent, width, height, starts=None):
    """A future of the RGBA image (height by width by 4) of the scene: read
    from the cache, or rendered by POV-Ray in a worker (POV-Ray's front end
    idles ~1 s per run, so several run at once)."""
    global _pool
    cached = (os.path.join(cache_dir, cache_key(C, rho, rgb, extent, width, height, starts) + ".png")
              if cache_dir else None)
    if cached and os.path.exists(cached):
        stats["cached"] += 1
        f = concurrent.futures.Future()
        f.set_result(plt.imread(cached))
        return f
    if _pool is None:
        _pool = concurrent.futures.ThreadPoolExecutor(max_workers=WORKERS)
    return _pool.submit(run_povray, scene(C, rho, rgb, extent, starts), width, height, cached)


def finish():
    """Waits for every pending render and puts the images into their axes
    (common.save calls it before saving a figure)."""
    while _pending:
        artist, future = _pending.pop(0)
        artist.set_data(future.result())


def axes_pixels(ax, dpi):
    """Width and height in pixels of the axes when the figure is saved at dpi."""
    fig = ax.get_figure()
    w, h = fig.get_size_inches()
    box = ax.get_position()
    return box.width * w * dpi, box.height * h * dpi


def draw_curve(ax, P, *, radius, radius_scale=1.0, view="top", color="curvature", cmap="viridis", vmax=None,
               dhat=None, oversample=2.0, dpi=150, max_pixels=1400, center=True):
    """Draws the closed curve P (n by 3) as a shaded tube of radius
    radius * radius_scale into ax, in the curve's length units (the image's
    extent is the projected curve plus the tube), and returns a ScalarMappable
    for a colour bar (None for contact or a fixed colour).

    view: "top", "front", "side" or (direction, up) (see the module comment).
    color: "curvature" (vmax: the top of the scale, default the 99th
    percentile), "contact" (needs dhat), a matplotlib colour, or n values.
    The image has oversample times the pixels the axes take at dpi (at most
    max_pixels on its longer side). center: subtract the centroid first.
    """
    P = np.asarray(P, dtype=float)
    if P.ndim != 2 or P.shape[1] != 3 or len(P) < 3:
        raise ValueError(f"draw_curve: expected an n by 3 array of points, got shape {P.shape}")
    Q = P - P.mean(axis=0) if center else P
    rgb, sm = vertex_colors(Q, color, cmap, vmax, dhat)
    place_render(ax, Q @ view_rotation(Q, view).T, radius * radius_scale, rgb, dpi, max_pixels, oversample)
    return sm


def place_render(ax, C, rho, rgb, dpi, max_pixels, oversample, starts=None):
    """Puts the render of the camera-frame points C (tubes of radius rho,
    vertex colours rgb; starts: the components' first vertices, None for one
    curve) into ax as a placeholder image filled by finish(), and sets the
    axes' limits to the image's extent (the projected curve plus the tube).
    The image has oversample times the pixels the axes take at dpi, at most
    max_pixels on its longer side."""
    pad = 1.5 * rho
    extent = (C[:, 0].min() - pad, C[:, 0].max() + pad, C[:, 1].min() - pad, C[:, 1].max() + pad)
    span_u, span_v = extent[1] - extent[0], extent[3] - extent[2]
    aw, ah = axes_pixels(ax, dpi)
    scale = oversample * min(aw / span_u, ah / span_v)  # pixels per length unit
    scale = min(scale, max_pixels / max(span_u, span_v))
    width, height = max(16, int(round(span_u * scale))), max(16, int(round(span_v * scale)))
    placeholder = np.zeros((height, width, 4))
    artist = ax.imshow(placeholder, extent=extent, origin="upper", interpolation="antialiased")
    _pending.append((artist, render_async(C, rho, rgb, extent, width, height, starts)))
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(extent[2], extent[3])
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    for s in ax.spines.values():
        s.set_visible(False)


def draw_link(ax, components, *, radius, colors, radius_scale=1.0, view="top", dpi=150, max_pixels=1400,
              oversample=2.0):
    """Draws a link (a list of closed curves, n_c by 3 each) as shaded tubes
    of radius radius * radius_scale in one POV-Ray scene, so that the
    components pass over and under one another as in a photograph; component
    c in colors[c] (matplotlib colours); the view as draw_curve's, of all
    vertices together (centred on their centroid)."""
    parts = [np.asarray(P, dtype=float) for P in components]
    if not parts or any(P.ndim != 2 or P.shape[1] != 3 or len(P) < 3 for P in parts):
        raise ValueError("draw_link: expected a list of n by 3 arrays of points")
    Q = np.vstack(parts)
    Q = Q - Q.mean(axis=0)
    starts = list(np.cumsum([0] + [len(P) for P in parts[:-1]]))
    rgb = np.vstack([np.broadcast_to(np.asarray(matplotlib.colors.to_rgb(c)), (len(P), 3))
                     for P, c in zip(parts, colors)])
    place_render(ax, Q @ view_rotation(Q, view).T, radius * radius_scale, rgb, dpi, max_pixels, oversample, starts)


def contact_legend(ax, **kwargs):
    """A legend for color='contact' (ax: an axes or a figure)."""
    from matplotlib.patches import Patch

    ax.legend(handles=[Patch(color=CONTACT_RED, label="in contact"), Patch(color=GREY, label="free")], **kwargs)
