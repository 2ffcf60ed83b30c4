"""Shared fixtures of the Python module's tests (label python).

CTest sets PYTHONPATH to the built module and EK_KNOTS_BIN (the knots command, to
compare with its JSON), EK_PEER_DATA (the peer implementation's curves) and
EK_TEST_DATASET (a small data set written by the fixture python_dataset).
"""
import json
import os
import subprocess

import numpy as np
import pytest

import elastic_knots as ek

# Keys whose values are measured times: they differ between two runs.
TIME_KEYS = {"seconds"}


def without_times(value):
    """The value with every key 'seconds' or 'time_*' removed (recursively)."""
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items()
                if k not in TIME_KEYS and not k.startswith("time_")}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


def json_part(result):
    """A Result as a dict without its numpy fields (the JSON part)."""
    return {k: v for k, v in result.to_dict().items() if not isinstance(v, np.ndarray)}


class Knots:
    """Runs the knots command."""

    def __init__(self, path):
        self.path = path

    def run(self, *args):
        p = subprocess.run([self.path, *map(str, args)], capture_output=True, text=True)
        return p.returncode, p.stdout, p.stderr

    def json(self, *args):
        status, out, err = self.run(*args, "--json")
        assert status == 0, err
        return json.loads(out)

    def error(self, *args):
        """The one-line message of a command that fails with bad input (exit 2), without its prefix."""
        status, _, err = self.run(*args)
        assert status == 2, err
        lines = err.strip().splitlines()
        assert len(lines) == 1, err
        return lines[0].split(": error: ", 1)[1]


@pytest.fixture(scope="session")
def knots():
    path = os.environ.get("EK_KNOTS_BIN")
    assert path and os.path.exists(path), "EK_KNOTS_BIN must name the knots command"
    return Knots(path)


@pytest.fixture(scope="session")
def peer():
    path = os.environ.get("EK_PEER_DATA")
    assert path and os.path.isdir(path), "EK_PEER_DATA must name the peer curves' folder"
    return path


@pytest.fixture(scope="session")
def dataset_path():
    path = os.environ.get("EK_TEST_DATASET")
    assert path and os.path.exists(path), "EK_TEST_DATASET must name the fixture's data set"
    return path


@pytest.fixture
def curve_file(tmp_path):
    """Writes an array as a curve file and returns its path."""
    def write(points, name="curve.obj"):
        path = str(tmp_path / name)
        ek.write_curve(path, points)
        return path
    return write


def trefoil(n=120):
    """A smooth (2, 3) torus knot, n vertices."""
    t = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
    r = 2.0 + np.cos(3.0 * t)
    return 10.0 * np.column_stack([r * np.cos(2.0 * t), r * np.sin(2.0 * t), np.sin(3.0 * t)])
