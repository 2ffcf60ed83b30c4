"""figures/render.py: the tube renders of the figures. The per-vertex
quantities against closed forms and brute force, the camera frames, and
POV-Ray's image of a curve that crosses itself: the strand nearer the viewer
hides the other at the crossing, and the image is not mirrored."""
import os
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "figures"))
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import render  # noqa: E402


def hairpin(gap):
    """Along y = 0 from x = 0 to 10 in unit edges, then back along y = gap."""
    return np.array([[i, 0.0, 0.0] for i in range(11)] + [[10 - i, gap, 0.0] for i in range(11)])


def crossing_curve(n=400):
    """A figure-eight in the xy-plane crossing itself at the origin, at
    t = pi/2 with z = +1 and at t = 3 pi/2 with z = -1."""
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return np.stack([10 * np.cos(t), 5 * np.sin(2 * t), np.sin(t)], axis=1), t


class Render(unittest.TestCase):
    def test_curvature_of_a_regular_polygon(self):
        n, R = 12, 3.0
        t = 2 * np.pi * np.arange(n) / n
        P = np.stack([R * np.cos(t), R * np.sin(t), 0 * t], axis=1)
        L = 2 * R * np.sin(np.pi / n)
        np.testing.assert_allclose(render.curvature(P), (2 * np.pi / n) / L, rtol=1e-12)

    def test_segment_distances_against_sampling(self):
        rng = np.random.default_rng(3)
        P = rng.normal(size=(9, 3))
        D = render.segment_distances(P)
        s = np.linspace(0, 1, 401)
        for i in range(9):
            for j in range(9):
                gap = min(abs(i - j), 9 - abs(i - j))
                if gap <= 1:
                    self.assertEqual(D[i, j], np.inf)
                    continue
                a = P[i] + s[:, None] * (P[(i + 1) % 9] - P[i])
                b = P[j] + s[:, None] * (P[(j + 1) % 9] - P[j])
                brute = np.linalg.norm(a[:, None] - b[None, :], axis=2).min()
                self.assertLessEqual(D[i, j], brute + 1e-12)
                self.assertGreater(D[i, j], brute - 0.01)  # the grid's resolution

    def test_contact_edges_of_a_hairpin(self):
        on, off = render.contact_edges(hairpin(0.3), 0.4), render.contact_edges(hairpin(0.3), 0.2)
        self.assertEqual(list(np.flatnonzero(~on)), [10, 21])  # the two short end edges
        self.assertFalse(off.any())

    def test_views_are_right_handed_rotations(self):
        P, _ = crossing_curve()
        for view in ("top", "front", "side", ((1.0, 2.0, -1.0), (0.0, 0.0, 1.0))):
            R = render.view_rotation(P, view)
            np.testing.assert_allclose(R @ R.T, np.eye(3), atol=1e-12)
            self.assertAlmostEqual(np.linalg.det(R), 1.0, places=12)
        # "top" looks along the smallest principal axis (here z)
        self.assertAlmostEqual(abs(render.view_rotation(P, "top")[2, 2]), 1.0, places=6)

    def render_crossing(self, direction, values):
        """The figure-eight seen along `direction` with y up, coloured by
        `values` (1: red, 0: blue). Returns the RGBA image."""
        P, _ = crossing_curve()
        fig, ax = plt.subplots(figsize=(4, 2))
        render.cache_dir = None
        render.draw_curve(ax, P, radius=0.6, view=(direction, (0.0, 1.0, 0.0)), color=values, cmap="coolwarm",
                          vmax=1.0, center=False)
        render.finish()
        data = np.asarray(ax.get_images()[0].get_array())
        plt.close(fig)
        return data

    @staticmethod
    def colour(img, rows, cols):
        """'red', 'blue' or None: the mean colour of the covered pixels in a window."""
        win = img[rows, cols]
        covered = win[..., 3] > 0.5
        if not covered.any():
            return None
        r, _, b = win[covered][:, :3].mean(axis=0)
        return "red" if r > b + 0.15 else "blue" if b > r + 0.15 else None

    @unittest.skipUnless(render.shutil.which("povray"), "POV-Ray missing (Debian package povray)")
    def test_the_nearer_strand_hides_the_other(self):
        _, t = crossing_curve()
        for direction, top in (((0.0, 0.0, -1.0), "red"), ((0.0, 0.0, 1.0), "blue")):
            img = self.render_crossing(direction, np.where(t < np.pi, 1.0, 0.0))  # red: the strand with z = +1
            h, w = img.shape[:2]
            self.assertEqual(self.colour(img, slice(h // 2 - 2, h // 2 + 3), slice(w // 2 - 2, w // 2 + 3)), top,
                             f"looking along {direction}")

    @unittest.skipUnless(render.shutil.which("povray"), "POV-Ray missing (Debian package povray)")
    def test_the_image_is_not_mirrored(self):
        P, _ = crossing_curve()
        # red: the lobe at x > 0. Seen from +z (looking along -z, y up) x points right; seen from -z, left.
        for direction, right in (((0.0, 0.0, -1.0), "red"), ((0.0, 0.0, 1.0), "blue")):
            img = self.render_crossing(direction, (P[:, 0] > 0).astype(float))
            h, w = img.shape[:2]
            self.assertEqual(self.colour(img, slice(None), slice(3 * w // 4, None)), right, f"along {direction}")
            self.assertEqual(self.colour(img, slice(None), slice(None, w // 4)), {"red": "blue", "blue": "red"}[right])

    @unittest.skipUnless(render.shutil.which("povray"), "POV-Ray missing (Debian package povray)")
    def test_renders_are_cached_by_content(self):
        P, _ = crossing_curve(60)
        with tempfile.TemporaryDirectory() as tmp:
            render.cache_dir = tmp
            for _ in range(2):
                fig, ax = plt.subplots(figsize=(2, 1))
                render.draw_curve(ax, P, radius=0.5)
                render.finish()
                plt.close(fig)
            self.assertEqual(len(os.listdir(tmp)), 1)
            self.assertGreaterEqual(render.stats["cached"], 1)
        render.cache_dir = None


if __name__ == "__main__":
    unittest.main(verbosity=2)
