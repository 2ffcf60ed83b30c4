"""The data-set explorer on a data set of links, in a real browser (label
browser): each component is its own closed tube in its own colour, and the
curve download has one closed loop per component. The fixture
browser_link_dataset builds the data set (tests/browser/CMakeLists.txt)."""
import io
import os
import sys
import unittest

import h5py
import numpy as np
from PIL import Image
from selenium.webdriver.common.by import By

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from explorer_driver import ExplorerCase, wait_for  # noqa: E402
class LinkExplorer(ExplorerCase):
    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        with h5py.File(cls.dataset, "r") as f:
            g = f["knots"]["borromean"]
            cls.components = [int(c) for c in g.attrs["components"]]
            cls.P = np.array(g["equilibria"][0])

    def test_components_in_their_own_colours_and_loops(self):
        self.browser.go(self.server.url + "#/view/borromean/0", "view")
        self.assertEqual(self.d.find_element(By.ID, "colour-mode").get_attribute("value"), "component")
        canvas = self.d.find_element(By.CSS_SELECTOR, ".viewer canvas")
        img = np.asarray(Image.open(io.BytesIO(canvas.screenshot_as_png)).convert("RGB")).astype(int)
        # tab10's first three colours, lit: the pixel closest in hue to each must be one of its own
        hues = {"#1f77b4": 0, "#ff7f0e": 0, "#2ca02c": 0}
        for css in hues:
            c = np.array([int(css[i:i + 2], 16) for i in (1, 3, 5)])
            direction = (c - c.mean()) / np.linalg.norm(c - c.mean())
            pix = img.reshape(-1, 3)
            chroma = pix - pix.mean(axis=1, keepdims=True)
            norm = np.linalg.norm(chroma, axis=1)
            hues[css] = int(np.sum((norm > 40) & (chroma @ direction > 0.95 * norm)))
        for css, count in hues.items():
            self.assertGreater(count, 200, f"component colour {css} covers {count} pixels: {hues}")
        self.assertEqual(self.browser.console_errors(), [])
        self.d.find_element(By.CSS_SELECTOR, ".download-curve").click()
        path = os.path.join(self.browser.downloads, "borromean_0.obj")
        wait_for(lambda: os.path.exists(path) and os.path.getsize(path) > 0)
        with open(path) as f:
            lines = f.read().splitlines()
        edges = [tuple(int(x) - 1 for x in l.split()[1:]) for l in lines if l.startswith("l ")]
        self.assertEqual(len(edges), len(self.P))
        nxt = dict(edges)
        loops, seen = [], set()
        for a, _ in edges:
            if a in seen:
                continue
            size, v = 0, a
            while v not in seen:
                seen.add(v)
                size, v = size + 1, nxt[v]
            loops.append(size)
        self.assertEqual(loops, self.components)


if __name__ == "__main__":
    unittest.main(verbosity=2)
