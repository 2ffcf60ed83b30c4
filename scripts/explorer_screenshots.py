#!/usr/bin/env python3
"""Screenshots of the explorer's main views and its load times, in Debian's
headless Chromium (the browser tests' driver, tests/browser/explorer_driver.py).

    scripts/explorer_screenshots.py --site DIR --out DIR

The site folder (written by `knots site`) is served by Python's static file
server, as any static server would; the browser's cache is disabled, so every
load fetches every file. Measured: the knot table drawn after a cold load of
the page (median and largest of --loads), the view of the knot with the most
equilibria and a 3D view after a click; the site's size. Writes <view>.png
and timing.json (with the date, commit and machine) into --out."""
import argparse
import datetime
import functools
import http.server
import json
import os
import platform
import statistics
import subprocess
import sys
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "browser"))
from explorer_driver import Browser  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.support.ui import Select  # noqa: E402


class Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def folder_bytes(path):
    return sum(os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(path) for f in fs)


def ready_ms(d):
    return float(d.execute_script("return document.body.dataset.readyAt"))


def click_to_ready(b, element, view):
    """Milliseconds from a click to the view being drawn, measured in the page."""
    b.driver.execute_script("window.ekClickAt = performance.now()")
    element.click()
    b.wait_ready(view)
    return ready_ms(b.driver) - float(b.driver.execute_script("return window.ekClickAt"))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--site", required=True, help="folder written by knots site")
    p.add_argument("--out", required=True, help="folder for the screenshots and timing.json")
    p.add_argument("--loads", type=int, default=5, help="cold loads of the page to time")
    a = p.parse_args()
    with open(os.path.join(a.site, "data", "site.json")) as f:
        site = json.load(f)
    os.makedirs(a.out, exist_ok=True)
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=a.site))
    threading.Thread(target=httpd.serve_forever, daemon=True).start()
    url = f"http://127.0.0.1:{httpd.server_address[1]}/"
    b = Browser()
    d = b.driver
    timing = {}
    try:
        d.execute_cdp_cmd("Network.setCacheDisabled", {"cacheDisabled": True})
        loads = []
        for _ in range(a.loads):
            d.get("about:blank")
            d.get(url + "#/knots")
            b.wait_ready("knots")
            loads.append(ready_ms(d))
        timing["table_after_cold_load_ms"] = {"median": statistics.median(loads), "max": max(loads), "loads": loads}
        d.save_screenshot(os.path.join(a.out, "knots.png"))
        knot = max(site["knots"], key=lambda k: (k["distinct"], k["equilibria"]))["name"]
        timing["knot_view_after_click_ms"] = click_to_ready(b, d.find_element(By.CSS_SELECTOR, f'tbody tr[data-knot="{knot}"]'), "knot")
        d.save_screenshot(os.path.join(a.out, "knot.png"))
        points = d.find_elements(By.CSS_SELECTOR, "#mds circle.point")
        timing["view3d_after_click_ms"] = click_to_ready(b, points[-1], "view")  # the topmost point (identical states overlap)
        d.save_screenshot(os.path.join(a.out, "view3d.png"))
        Select(d.find_element(By.ID, "compare")).select_by_index(2)
        b.wait_ready("view")
        Select(d.find_element(By.ID, "thickness")).select_by_value("4")  # 4 r: the tubes' shading shows
        time.sleep(0.5)
        d.save_screenshot(os.path.join(a.out, "compare.png"))
        d.get(url + "#/query?where=sphericity%3C0.05&where=threedim%3C0.1&sort=energy%3Aasc&limit=50")
        b.wait_ready("query")
        d.save_screenshot(os.path.join(a.out, "query.png"))
        d.get(url + "#/milnor")
        b.wait_ready("milnor")
        bars = d.find_elements(By.CSS_SELECTOR, "#milnor rect.bar")
        bars[len(bars) // 2].click()
        d.save_screenshot(os.path.join(a.out, "milnor.png"))
        errors = b.console_errors()
    finally:
        b.close()
        httpd.shutdown()
    data = os.path.join(a.site, "data")
    timing["site_bytes"] = folder_bytes(a.site)
    timing["data_bytes"] = folder_bytes(data)
    timing["knot_data_bytes_largest"] = max(os.path.getsize(os.path.join(data, "knots", f))
                                            for f in os.listdir(os.path.join(data, "knots")))
    timing["knot_view"] = knot
    timing["knots"] = len(site["knots"])
    timing["equilibria"] = site["attributes"]["rows"]
    timing["console_errors"] = [e["message"] for e in errors]
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
    timing["measured"] = {"date": datetime.date.today().isoformat(), "commit": commit.stdout.strip(),
                          "machine": f"{platform.node()} ({os.cpu_count()} cores)",
                          "load_average": os.getloadavg()[0]}
    with open(os.path.join(a.out, "timing.json"), "w") as f:
        json.dump(timing, f, indent=1)
    t = timing["table_after_cold_load_ms"]
    print(f"explorer of {timing['knots']} knots, {timing['equilibria']} equilibria: site {timing['site_bytes'] / 1e6:.2f} MB "
          f"(data {timing['data_bytes'] / 1e6:.2f} MB); knot table drawn {t['median']:.0f} ms after a cold load "
          f"(median of {len(t['loads'])}, largest {t['max']:.0f} ms); knot view {timing['knot_view_after_click_ms']:.0f} ms "
          f"and 3D view {timing['view3d_after_click_ms']:.0f} ms after a click; screenshots in {a.out}")
    if errors:
        sys.exit(f"console errors: {timing['console_errors']}")


if __name__ == "__main__":
    main()
