"""Fixtures of the Python module's tests: where the sources, the command line and the shared
motions are. ctest runs these with PYTHONPATH at the build's python/ folder (tests/python/CMakeLists.txt)."""

import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("CASKDEM_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BINARY = pathlib.Path(os.environ.get("CASKDEM_BIN", SOURCE / "build" / "src" / "caskdem"))


@pytest.fixture(scope="session")
def source():
    return SOURCE


@pytest.fixture(scope="session")
def command_line():
    """Runs the caskdem command line; returns its completed process (check=True)."""

    def call(*arguments, cwd=None):
        return subprocess.run([str(BINARY), *map(str, arguments)], cwd=cwd, check=True, capture_output=True, text=True)

    return call


@pytest.fixture(scope="session")
def mixed_outcomes():
    """The planar test ensemble whose realisations stand, rock, slide and tip over."""
    import caskdem

    return caskdem.load_ensemble(SOURCE / "tests/ensemble/data/mixed-outcomes.toml")


def bits(values):
    """An array's bits, to compare floats exactly (NaN with NaN, -0 apart from 0)."""
    import numpy as np

    a = np.ascontiguousarray(values)
    return a.view(np.uint64) if a.dtype == np.float64 else a
