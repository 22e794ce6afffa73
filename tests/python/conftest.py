"""Paths for the tests of the Python module rbcal, set by ctest (tests/python/CMakeLists.txt):
RBCAL_EXE (the command line), RBCAL_SOURCE (the source tree), RBCAL_SCRATCH (a folder to write)."""
import os
import pathlib

import pytest


@pytest.fixture(scope="session")
def source():
    return pathlib.Path(os.environ.get("RBCAL_SOURCE", pathlib.Path(__file__).parents[2]))


@pytest.fixture(scope="session")
def exe():
    return os.environ["RBCAL_EXE"]


@pytest.fixture(scope="session")
def scratch(tmp_path_factory):
    folder = os.environ.get("RBCAL_SCRATCH")
    return pathlib.Path(folder) if folder else tmp_path_factory.mktemp("rbcal")
