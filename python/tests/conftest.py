"""Shared fixtures of the Python package's tests. CTest (python/tests/
CMakeLists.txt) runs each test file with PYTHONPATH at the staged package
and these environment variables naming what the tests compare with:
  CREEPWORK_SOURCE_DIR   the source tree (header, generator, docs, examples)
  CREEPWORK_TEST_DATA_DIR reference data (tests/data: Kalker's published values)
  CREEPWORK_CLI          the creepwork program (bitwise comparisons)
  CREEPWORK_C_QUICKSTART the C quick start program
  CREEPWORK_LAYOUT_PROBE layout_probe.c compiled with -g; CREEPWORK_READELF
A test whose comparison target was not built is not registered by CTest,
so a missing variable here is an error, not a skip."""

import os
import subprocess
import sys

import pytest


def env_path(name):
    value = os.environ.get(name)
    if not value:
        raise RuntimeError("%s is not set: run the tests through CTest (ctest -L python)" % name)
    return value


@pytest.fixture(scope="session")
def source_dir():
    return env_path("CREEPWORK_SOURCE_DIR")


@pytest.fixture(scope="session")
def test_data_dir():
    return env_path("CREEPWORK_TEST_DATA_DIR")


@pytest.fixture(scope="session")
def cli():
    return env_path("CREEPWORK_CLI")


def run_cli(cli_path, *args):
    """Runs the CLI; returns (stdout, stderr); fails the test on a non-zero exit."""
    p = subprocess.run([cli_path] + [str(a) for a in args], capture_output=True, text=True)
    if p.returncode != 0:
        raise AssertionError("creepwork %s exited %d: %s" % (" ".join(map(str, args)),
                                                              p.returncode, p.stderr))
    return p.stdout, p.stderr


@pytest.fixture(scope="session")
def generator(source_dir):
    """The generate_layout module of the source tree."""
    sys.path.insert(0, os.path.join(source_dir, "python"))
    try:
        import generate_layout
    finally:
        sys.path.pop(0)
    return generate_layout
