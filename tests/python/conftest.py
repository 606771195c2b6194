"""Shared fixtures of the Python module's tests (run by ctest with PYTHONPATH at the module and
TUBEMESH_CLI at the tubemesh program)."""
import os

import pytest

import tubemesh


@pytest.fixture(scope="session")
def cli():
    return os.environ["TUBEMESH_CLI"]


@pytest.fixture(scope="session")
def crankshaft():
    """The paper's third example at its reference size: a small full hybrid mesh."""
    return tubemesh.mesh("paper-ex3", size=40)
