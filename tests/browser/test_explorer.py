"""The data-set explorer (`knots serve`, `knots site`) in a real browser:
Debian's headless Chromium driven by chromedriver (tests/browser/explorer_driver.py),
on a data set the test fixture built (EK_EXPLORER_DATASET). Every count the
page shows is checked against the data-set file (read with h5py) or against
the command line (`knots cluster`, `knots query`) on the same file.

Run one test: python3 test_explorer.py Explorer.test_query_matches_the_cli
Environment: EK_KNOTS (the knots program), EK_EXPLORER_DATASET, KNOT_TABLE;
EK_SCREENSHOTS=DIR also saves a screenshot of each view."""
import http.client
import io
import json
import os
import subprocess
import sys
import tempfile
import threading
import time
import unittest
import functools
import http.server

import h5py
import numpy as np
from PIL import Image
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from explorer_driver import ExplorerCase, wait_for  # noqa: E402

KNOTS = os.environ.get("EK_KNOTS", "knots")
DATASET = os.environ.get("EK_EXPLORER_DATASET", "")
SHOTS = os.environ.get("EK_SCREENSHOTS")


def knots_json(*args):
    out = subprocess.run([KNOTS, *args, "--json"], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def dataset_facts():
    """Knot names in file order, crossing numbers, equilibria counts and similarity matrices, read with h5py."""
    with h5py.File(DATASET, "r") as f:
        names = [n.decode() if isinstance(n, bytes) else n for n in f["knot_names"][:]]
        facts = {}
        for n in names:
            g = f["knots"][n]
            facts[n] = {"crossings": int(g.attrs["crossing_number"]), "m": int(g["equilibria"].shape[0]),
                        "similarity": np.array(g["similarity"]), "equilibria": np.array(g["equilibria"])}
    return names, facts


class Explorer(ExplorerCase):
    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.names, cls.facts = dataset_facts()
        # the knot with the most distinct states (then equilibria), for the per-knot views
        cls.knot = max(cls.names, key=lambda n: (len(knots_json("cluster", DATASET, n, "--cut", "0.02")["clusters"])
                                                 if cls.facts[n]["m"] else 0, cls.facts[n]["m"]))

    def shot(self, name, element=None):
        if SHOTS:
            os.makedirs(SHOTS, exist_ok=True)
            path = os.path.join(SHOTS, f"{name}.png")
            element.screenshot(path) if element else self.d.save_screenshot(path)

    def open(self, hash_, ready):
        self.browser.go(self.server.url + hash_, ready)

    # ---- the knot table -----------------------------------------------------------------

    def test_loads_without_console_errors(self):
        self.d.get_log("browser")  # drop earlier entries
        t0 = time.perf_counter()
        self.open("", "knots")
        seconds = time.perf_counter() - t0
        print(f"knot table drawn {seconds:.2f} s after the request")
        self.assertEqual(self.browser.console_errors(), [])
        self.assertIn("knot types", self.d.find_element(By.ID, "knot-count").text)
        self.shot("knots")

    def test_table_has_one_row_per_knot_and_filters(self):
        self.open("#/knots", "knots")
        rows = self.d.find_elements(By.CSS_SELECTOR, "tbody tr[data-knot]")
        self.assertEqual(sorted(r.get_attribute("data-knot") for r in rows), sorted(self.names))
        box = self.d.find_element(By.ID, "filter-crossingsMin")
        box.send_keys(Keys.CONTROL, "a")
        box.send_keys("5")
        expected = sum(1 for n in self.names if self.facts[n]["crossings"] >= 5)
        rows = self.d.find_elements(By.CSS_SELECTOR, "tbody tr[data-knot]")
        self.assertEqual(len(rows), expected)
        self.assertTrue(0 < expected < len(self.names), "the filter must keep some knots and drop others")
        self.assertEqual(self.d.find_element(By.ID, "knot-count").text, f"{expected} of {len(self.names)} knot types")
        box.send_keys(Keys.CONTROL, "a")
        box.send_keys(Keys.DELETE)
        self.assertEqual(len(self.d.find_elements(By.CSS_SELECTOR, "tbody tr[data-knot]")), len(self.names))

    # ---- one knot -----------------------------------------------------------------------

    def open_knot_by_click(self):
        self.open("#/knots", "knots")
        self.d.find_element(By.CSS_SELECTOR, f'tbody tr[data-knot="{self.knot}"]').click()
        self.browser.wait_ready("knot")

    def test_mds_map_has_one_point_per_equilibrium(self):
        self.open_knot_by_click()
        points = self.d.find_elements(By.CSS_SELECTOR, "#mds circle.point")
        self.assertEqual(len(points), self.facts[self.knot]["m"])
        rows = self.d.find_elements(By.CSS_SELECTOR, "tbody tr[data-index]")
        self.assertEqual(len(rows), self.facts[self.knot]["m"])
        self.shot("knot")

    def test_cut_slider_gives_the_clusters_of_the_cli(self):
        self.open_knot_by_click()
        slider = self.d.find_element(By.ID, "cut-slider")
        counts = set()
        for steps in (0, 10, 40, 100, 300, 2000):  # the slider moves in steps of 0.0005
            slider.send_keys(Keys.HOME)
            if steps:
                slider.send_keys(Keys.ARROW_RIGHT * steps)
            cut = slider.get_attribute("value")
            shown = self.d.find_element(By.ID, "cluster-count")
            self.assertEqual(shown.get_attribute("data-cut"), cut)
            cli = knots_json("cluster", DATASET, self.knot, "--cut", cut)
            self.assertEqual(int(shown.text), len(cli["clusters"]), f"cut {cut}")
            counts.add(len(cli["clusters"]))
        self.assertGreater(len(counts), 1, "the cuts tried must give different cluster counts")

    def fetched(self):
        """The site files this page load has fetched so far (paths below the server's root)."""
        names = self.d.execute_script("return performance.getEntriesByType('resource').map(e => e.name)")
        return [n.split(self.server.url, 1)[-1].lstrip("/") for n in names]

    def test_a_knot_loads_only_its_own_files(self):
        # a fresh page opened at an equilibrium: the table's site.json and
        # that knot's two files, never another knot's or every equilibrium's
        # attributes (so that a site of the whole table stays usable); the
        # query view, which filters across knots, loads attributes.bin
        self.d.get("about:blank")
        self.open(f"#/view/{self.knot}/0", "view")
        data = [f for f in self.fetched() if f.startswith("data/")]
        self.assertIn("data/site.json", data)
        knot_files = sorted(f for f in data if f.startswith("data/knots/"))
        self.assertEqual(len(knot_files), 2, knot_files)
        self.assertTrue(all(f.split("/")[-1].rsplit(".", 1)[0] == knot_files[0].split("/")[-1].rsplit(".", 1)[0]
                            for f in knot_files), knot_files)
        self.assertNotIn("data/attributes.bin", data)
        self.open("#/query", "query")
        self.assertIn("data/attributes.bin", self.fetched())

    def canvas_coverage(self, box):
        """Share of the canvas's pixels that differ from its white background."""
        canvas = box.find_element(By.TAG_NAME, "canvas")
        img = np.asarray(Image.open(io.BytesIO(canvas.screenshot_as_png)).convert("RGB")).astype(int)
        return float(np.mean(np.abs(img - 255).sum(axis=2) > 30))

    def test_state_pictures_are_the_clusters_by_energy_and_open_3d(self):
        # one picture per distinct state at the cut (Fig. 2's row), in the
        # order of `knots cluster` (by energy), each of its representative
        # and drawn; a picture opens that equilibrium in 3D
        self.open_knot_by_click()
        slider = self.d.find_element(By.ID, "cut-slider")
        for steps in (0, 100):
            slider.send_keys(Keys.HOME)
            if steps:
                slider.send_keys(Keys.ARROW_RIGHT * steps)
            cut = slider.get_attribute("value")
            cli = knots_json("cluster", DATASET, self.knot, "--cut", cut)["clusters"]
            shown = self.d.find_elements(By.CSS_SELECTOR, "#state-gallery figure.state")
            self.assertEqual([int(f.get_attribute("data-index")) for f in shown],
                             [c["representative"] for c in cli][:40], f"cut {cut}")
        for figure in shown:
            self.assertGreater(self.canvas_coverage(figure), 0.02, "a state's picture must show its tube")
        first = shown[0].get_attribute("data-index")
        shown[0].click()
        self.browser.wait_ready("view")
        self.d.find_element(By.CSS_SELECTOR, f'.viewer[data-index="{first}"]')
        self.assertEqual(self.browser.console_errors(), [])

    def test_unseen_states_as_the_cli_estimates_them(self):
        # the knot page's estimate of the states not yet seen, at the site's
        # cut, is `knots cluster --json`'s at that cut
        self.open_knot_by_click()
        cut = self.d.find_element(By.ID, "cut-slider").get_attribute("value")
        u = knots_json("cluster", DATASET, self.knot, "--cut", cut)["unseen"]
        text = self.d.find_element(By.ID, "unseen").text
        js_round = lambda x: int(x + 0.5)  # Math.round of a positive number (Python's round() ties to even)
        self.assertIn(f"{u['found']} found, about {js_round(u['estimated'])} in all", text)
        self.assertIn(f"interval {js_round(u['lower'])} to {js_round(u['upper'])}", text)

    def test_clicked_point_opens_a_3d_view_that_draws(self):
        self.open_knot_by_click()
        point = self.d.find_elements(By.CSS_SELECTOR, "#mds circle.point")[-1]
        index = point.get_attribute("data-index")
        point.click()
        self.browser.wait_ready("view")
        box = self.d.find_element(By.CSS_SELECTOR, f'.viewer[data-index="{index}"]')
        self.assertEqual(box.get_attribute("data-drawn"), "1")
        thin = self.canvas_coverage(box)
        self.assertGreater(thin, 0.002, "the tube must cover some pixels")
        self.select(self.d.find_element(By.ID, "thickness"), "4")  # 4 r
        wait_for(lambda: self.canvas_coverage(box) > 1.5 * thin)
        self.select(self.d.find_element(By.ID, "colour-mode"), "contact")
        self.assertGreater(self.canvas_coverage(box), 0.002)
        self.assertEqual(self.browser.console_errors(), [])
        self.shot("view3d")

    def test_two_equilibria_side_by_side_with_their_similarity(self):
        m = self.facts[self.knot]["m"]
        self.open(f"#/view/{self.knot}/0", "view")
        self.d.execute_script("delete document.body.dataset.ready")
        self.select(self.d.find_element(By.ID, "compare"), str(m - 1))
        self.browser.wait_ready("view")
        wait_for(lambda: len(self.d.find_elements(By.CSS_SELECTOR, ".viewer[data-drawn]")) == 2)
        for box in self.d.find_elements(By.CSS_SELECTOR, ".viewer"):
            self.assertGreater(self.canvas_coverage(box), 0.002)
        text = self.d.find_element(By.ID, "similarity").text
        shown = float(text.split()[1])
        self.assertAlmostEqual(shown, self.facts[self.knot]["similarity"][0, m - 1], delta=1e-3, msg=text)
        self.shot("compare")

    def test_curve_obj_download(self):
        self.open(f"#/view/{self.knot}/1", "view")
        self.d.find_element(By.CSS_SELECTOR, ".download-curve").click()
        path = os.path.join(self.browser.downloads, f"{self.knot}_1.obj")
        wait_for(lambda: os.path.exists(path) and os.path.getsize(path) > 0)
        with open(path) as f:
            lines = f.read().splitlines()
        v = np.array([[float(x) for x in l.split()[1:]] for l in lines if l.startswith("v ")])
        edges = [l for l in lines if l.startswith("l ")]
        P = self.facts[self.knot]["equilibria"][1]
        self.assertEqual(v.shape, P.shape)
        self.assertEqual(len(edges), len(P))
        np.testing.assert_allclose(v, P, rtol=0, atol=1e-5 * np.abs(P).max())  # float32 positions

    # ---- cross-knot queries and the Milnor histogram ------------------------------------

    def run_query_form(self, knot, conditions, sort, direction, limit):
        self.open("#/query", "query")
        if knot:
            self.select(self.d.find_element(By.ID, "query-knot"), knot)
        for k, (attr, op, value) in enumerate(conditions):
            if k:
                self.d.find_element(By.ID, "query-add").click()
            row = self.d.find_elements(By.CSS_SELECTOR, "#conditions .condition")[k]
            self.select(row.find_element(By.CLASS_NAME, "cond-attr"), attr)
            self.select(row.find_element(By.CLASS_NAME, "cond-op"), op)
            row.find_element(By.CLASS_NAME, "cond-value").send_keys(value)
        if sort:
            self.select(self.d.find_element(By.ID, "query-sort"), sort)
            self.select(self.d.find_element(By.ID, "query-dir"), direction)
        if limit is not None:
            self.d.find_element(By.ID, "query-limit").send_keys(str(limit))
        self.d.execute_script("delete document.body.dataset.ready")
        self.d.find_element(By.ID, "query-run").click()
        self.browser.wait_ready("query")
        return [(r.get_attribute("data-knot"), int(r.get_attribute("data-index")))
                for r in self.d.find_elements(By.CSS_SELECTOR, "#query-table tbody tr")]

    def select(self, element, value):
        from selenium.webdriver.support.ui import Select

        Select(element).select_by_value(value)

    def test_query_matches_the_cli(self):
        cases = [
            (None, [("threedim", "<", "0.1")], "energy", "desc", 12),
            (None, [("energy", ">=", "0.5"), ("sphericity", "<", "0.3")], "total_curvature", "asc", None),
            (self.knot, [("writhe", "!=", "0")], "threedim", "desc", None),
        ]
        for knot, conditions, sort, direction, limit in cases:
            shown = self.run_query_form(knot, conditions, sort, direction, limit)
            args = ["query", DATASET, "--sort", f"{sort}:{direction}"]
            for a, op, v in conditions:
                args += ["--where", f"{a}{op}{v}"]
            if knot:
                args += ["--knot", knot]
            if limit is not None:
                args += ["--limit", str(limit)]
            cli = [(r["knot"], r["index"]) for r in knots_json(*args)["rows"]]
            self.assertEqual(shown, cli, f"{conditions} sorted by {sort}:{direction}")
            self.assertEqual(int(self.d.find_element(By.ID, "query-count").text), len(cli))
        self.assertGreater(len(cli), 0)
        self.shot("query")
        self.d.find_element(By.CSS_SELECTOR, "#query-table tbody tr").click()
        self.browser.wait_ready("view")

    def test_milnor_histogram_lists_knots_and_opens_them(self):
        self.open("#/milnor", "milnor")
        bins = sorted({int(b.get_attribute("data-bin")) for b in self.d.find_elements(By.CSS_SELECTOR, "#milnor rect.bar")})
        listed = []
        for b in bins:
            self.d.find_element(By.CSS_SELECTOR, f'#milnor rect.bar[data-bin="{b}"]').click()
            listed += [a.get_attribute("data-knot") for a in self.d.find_elements(By.CSS_SELECTOR, "#milnor-list a")]
        with_equilibria = [n for n in self.names if self.facts[n]["m"] > 0]
        self.assertEqual(sorted(listed), sorted(with_equilibria))
        self.shot("milnor")
        link = self.d.find_elements(By.CSS_SELECTOR, "#milnor-list a")[0]
        name = link.get_attribute("data-knot")
        link.click()
        self.browser.wait_ready("knot")
        self.assertEqual(self.d.find_element(By.TAG_NAME, "h2").text, name)

    # ---- the static site and the server's refusals --------------------------------------

    def test_static_site_from_another_server_and_from_disk(self):
        with tempfile.TemporaryDirectory() as tmp:
            site = os.path.join(tmp, "site")
            subprocess.run([KNOTS, "site", DATASET, "-o", site], check=True, capture_output=True)
            class Quiet(http.server.SimpleHTTPRequestHandler):
                def log_message(self, *args):
                    pass

            handler = functools.partial(Quiet, directory=site)
            httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
            threading.Thread(target=httpd.serve_forever, daemon=True).start()
            try:
                self.browser.go(f"http://127.0.0.1:{httpd.server_address[1]}/#/knots", "knots")
                self.assertEqual(len(self.d.find_elements(By.CSS_SELECTOR, "tbody tr[data-knot]")), len(self.names))
            finally:
                httpd.shutdown()
                httpd.server_close()
            # from disk: Chromium refuses ES modules from file:// URLs, so the page says how to serve it
            self.d.get("file://" + os.path.join(site, "index.html"))
            boot = wait_for(lambda: "knots serve" in self.d.find_element(By.ID, "boot").text and
                            self.d.find_element(By.ID, "boot").text, timeout=20)
            self.assertIn("file://", boot)

    def test_server_answers_only_site_files(self):
        port = int(self.server.url.rsplit(":", 1)[1].strip("/"))

        def status(method, target):
            c = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
            c.putrequest(method, target, skip_host=False, skip_accept_encoding=True)
            c.endheaders()
            r = c.getresponse()
            r.read()
            c.close()
            return r.status

        self.assertEqual(status("GET", "/data/site.json"), 200)
        self.assertEqual(status("GET", "/../../../etc/passwd"), 403)
        self.assertEqual(status("GET", "/js/%2e%2e/%2e%2e/etc/passwd"), 403)
        self.assertEqual(status("GET", "/etc/passwd"), 404)
        self.assertEqual(status("POST", "/index.html"), 405)


if __name__ == "__main__":
    unittest.main(verbosity=2)
