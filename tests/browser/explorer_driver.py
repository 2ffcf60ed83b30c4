"""Shared plumbing of the explorer's browser tests and screenshots: Debian's
Chromium driven by Debian's chromedriver through Selenium, headless, with a
fresh profile and no network beyond 127.0.0.1; `knots serve` started on a free
loopback port."""
import os
import re
import shutil
import subprocess
import tempfile
import time
import unittest

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.support.ui import WebDriverWait

CHROMIUM = os.environ.get("EK_CHROMIUM", "/usr/bin/chromium")
CHROMEDRIVER = os.environ.get("EK_CHROMEDRIVER", "/usr/bin/chromedriver")
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage", "--window-size=1400,1000"]


class Server:
    """`knots serve DATASET --port 0`; url is http://127.0.0.1:PORT/."""

    def __init__(self, knots, dataset, extra=()):
        self.proc = subprocess.Popen([knots, "serve", dataset, "--port", "0", *extra], stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE, text=True)
        line = self.proc.stdout.readline()
        m = re.search(r"(http://127\.0\.0\.1:\d+/)", line)
        if not m:
            self.proc.kill()
            raise RuntimeError(f"knots serve did not start: {line!r} {self.proc.stderr.read()!r}")
        self.url = m.group(1)

    def stop(self):
        self.proc.terminate()
        try:
            out, _ = self.proc.communicate(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            out, _ = self.proc.communicate()
        return self.proc.returncode, out


class Browser:
    """Headless Chromium with its own empty profile and a download folder."""

    def __init__(self, extra_flags=()):
        self.profile = tempfile.mkdtemp(prefix="ek-chromium-")
        self.downloads = os.path.join(self.profile, "downloads")
        os.makedirs(self.downloads)
        options = webdriver.ChromeOptions()
        options.binary_location = CHROMIUM
        for f in [*FLAGS, f"--user-data-dir={self.profile}/profile", *extra_flags]:
            options.add_argument(f)
        options.add_experimental_option("prefs", {"download.default_directory": self.downloads,
                                                  "download.prompt_for_download": False})
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
        self.driver = webdriver.Chrome(service=Service(executable_path=CHROMEDRIVER), options=options)
        self.driver.set_page_load_timeout(60)

    def wait_ready(self, name, timeout=60):
        """Waits until the page marks the view `name` as drawn (body[data-ready])."""
        WebDriverWait(self.driver, timeout).until(
            lambda d: d.execute_script("return document.body.dataset.ready") == name
            or d.find_element(By.ID, "error").is_displayed())
        err = self.driver.find_element(By.ID, "error")
        if err.is_displayed():
            raise AssertionError(f"the page reports: {err.text}")

    def go(self, url, ready):
        self.driver.get(url)
        self.wait_ready(ready)

    def console_errors(self):
        return [e for e in self.driver.get_log("browser") if e.get("level") == "SEVERE"]

    def close(self):
        try:
            self.driver.quit()
        finally:
            shutil.rmtree(self.profile, ignore_errors=True)


def wait_for(predicate, timeout=30, step=0.1):
    end = time.time() + timeout
    while time.time() < end:
        value = predicate()
        if value:
            return value
        time.sleep(step)
    raise AssertionError("timed out")


class ExplorerCase(unittest.TestCase):
    """Tests of the explorer of the data set EK_EXPLORER_DATASET, served by
    `knots serve` (EK_KNOTS) to one browser for the whole class; skipped when
    the data set is missing (its CTest fixture builds it)."""

    dataset = os.environ.get("EK_EXPLORER_DATASET", "")
    knots_bin = os.environ.get("EK_KNOTS", "knots")

    @classmethod
    def setUpClass(cls):
        if not cls.dataset or not os.path.exists(cls.dataset):
            raise unittest.SkipTest("EK_EXPLORER_DATASET is not a file (the fixture builds it)")
        cls.server = Server(cls.knots_bin, cls.dataset)
        cls.browser = Browser()
        cls.d = cls.browser.driver

    @classmethod
    def tearDownClass(cls):
        cls.browser.close()
        cls.server.stop()
