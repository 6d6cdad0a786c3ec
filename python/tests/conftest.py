"""Shared helpers of the pytest suites: the build tree's CLI (DISKLAB_CLI, set by ctest) and a
reader of its CSV output."""
import io
import os
import subprocess

import numpy as np
import pytest


@pytest.fixture(scope="session")
def cli():
    exe = os.environ.get("DISKLAB_CLI")
    if not exe:
        pytest.skip("DISKLAB_CLI is not set (ctest sets it)")

    def run(*args, header=True):
        """Runs `disklab ARGS` and returns its CSV on stdout as a float64 array (without the
        header line, when it has one)."""
        out = subprocess.run([exe, *map(str, args)], check=True, capture_output=True, text=True,
                             env={**os.environ, "DISKLAB_QUIET": "1"}).stdout
        return np.loadtxt(io.StringIO(out), delimiter=",", skiprows=1 if header else 0,
                          ndmin=2)

    return run
