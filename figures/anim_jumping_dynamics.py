"""Animation of a jumping knot released in time (exp_jumping_dynamics): the
figure knot's frictionless release, every frame of frames/<knot>/ up to
--frames of them, rendered as shaded tubes (POV-Ray, the figures' look) from
one fixed oblique camera and assembled by ffmpeg into <out>/<name>.gif and
<out>/<name>.mp4. Reads the experiment's results only.

  anim_jumping_dynamics.py --results RESULTS --out DIR [--frames 80] [--fps 12] [--width 480]
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

plt.rcParams["figure.max_open_warning"] = 0  # every frame stays open until its render is placed
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import render  # noqa: E402
from common import read_csv, read_obj, read_summary  # noqa: E402

SCALE = 2.0  # wire drawn at this multiple of its radius
VIEW = ((0.35, -1.0, -0.55), (0.0, 0.0, 1.0))  # looking from the front, a little from above; z up


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--results", required=True, help="results root (holding jumping_dynamics/)")
    p.add_argument("--out", required=True, help="folder for the GIF and the MP4")
    p.add_argument("--frames", type=int, default=80, help="frames of the animation at most")
    p.add_argument("--fps", type=int, default=12, help="frames per second")
    p.add_argument("--width", type=int, default=480, help="width in pixels")
    p.add_argument("--name", default="anim_jumping_dynamics", help="file name without extension")
    a = p.parse_args()
    if a.frames < 2 or a.fps < 1 or a.width < 64:
        p.error("--frames >= 2, --fps >= 1 and --width >= 64")
    ffmpeg = shutil.which("ffmpeg")
    if not ffmpeg:
        sys.exit("anim_jumping_dynamics: ffmpeg is missing (Debian package ffmpeg; make deps installs it)")
    d = f"{a.results}/jumping_dynamics"
    s = read_summary(a.results, "jumping_dynamics")
    knot = s["figure_knot"]
    rows = [r for r in read_csv(f"{d}/dynamics.csv")
            if r["knot"] == knot and float(r["mu"]) == 0.0 and float(r["time_step"]) == s["time_step"]]
    traj = read_csv(f"{d}/{rows[0]['trajectory']}")
    files = sorted(f for f in os.listdir(f"{d}/frames/{knot}") if f.endswith(".obj"))
    picks = sorted(set(round(k * (len(files) - 1) / (min(a.frames, len(files)) - 1))
                       for k in range(min(a.frames, len(files)))))
    curves = [read_obj(f"{d}/frames/{knot}/{files[k]}") for k in picks]
    # one camera and one box for every frame, centred on the start's centroid
    centre = curves[0].mean(axis=0)
    R = render.view_rotation(curves[0], VIEW)
    projected = np.vstack([(C - centre) @ R.T for C in curves])
    margin = s["radius"] * SCALE * 2
    lo, hi = projected[:, :2].min(axis=0) - margin, projected[:, :2].max(axis=0) + margin
    vmax = float(np.percentile(np.concatenate([render.curvature(C) for C in curves]), 99))
    aspect = (hi[1] - lo[1] + 0.25 * (hi[0] - lo[0])) / (hi[0] - lo[0])
    dpi = 100
    os.makedirs(a.out, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        figs = []
        for j, (k, C) in enumerate(zip(picks, curves)):
            fig = plt.figure(figsize=(a.width / dpi, a.width * aspect / dpi), dpi=dpi)
            ax = fig.add_axes([0, 0, 1, 0.82])
            render.draw_curve(ax, C - centre, radius=s["radius"], radius_scale=SCALE, view=VIEW, vmax=vmax, dpi=dpi,
                              max_pixels=2 * a.width, center=False)
            ax.set_xlim(lo[0], hi[0])
            ax.set_ylim(lo[1], hi[1])
            ax.set_axis_off()
            t, td = float(traj[k]["time"]), float(traj[k]["threedim"])
            fig.text(0.5, 0.93, f"{knot} released at t = 0, no friction: t = {t:.0f}, 3D-ness {td:.2f}",
                     ha="center", fontsize=8)
            figs.append((fig, f"{tmp}/{j:05d}.png"))
        render.finish()
        for fig, path in figs:
            fig.savefig(path, dpi=dpi)
            plt.close(fig)
        frames = f"{tmp}/%05d.png"
        gif, mp4 = f"{a.out}/{a.name}.gif", f"{a.out}/{a.name}.mp4"
        palette = f"{tmp}/palette.png"
        quiet = ["-hide_banner", "-loglevel", "error", "-y"]
        subprocess.run([ffmpeg, *quiet, "-framerate", str(a.fps), "-i", frames, "-vf", "palettegen=max_colors=128",
                        palette], check=True)
        subprocess.run([ffmpeg, *quiet, "-framerate", str(a.fps), "-i", frames, "-i", palette, "-lavfi",
                        "paletteuse=dither=bayer:bayer_scale=4", gif + ".tmp.gif"], check=True)
        os.replace(gif + ".tmp.gif", gif)
        subprocess.run([ffmpeg, *quiet, "-framerate", str(a.fps), "-i", frames, "-c:v", "libx264", "-pix_fmt",
                        "yuv420p", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", mp4 + ".tmp.mp4"], check=True)
        os.replace(mp4 + ".tmp.mp4", mp4)
    print(f"wrote {gif} ({os.path.getsize(gif) // 1024} kB) and {mp4} ({os.path.getsize(mp4) // 1024} kB): "
          f"{len(picks)} frames of {knot}, {render.stats['renders']} renders")


if __name__ == "__main__":
    main()
