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


@pytest.fixture
def two_boxes(tmp_path):
    """Writes a STEP file of two 1-wide boxes (the second 2 wide when apart), the second starting
    at x = start (1: they share the face x = 1); returns its path."""

    def write(start):
        import gmsh

        step = str(tmp_path / "two.step")
        gmsh.initialize()
        try:
            gmsh.option.setNumber("General.Terminal", 0)
            gmsh.model.occ.addBox(0, 0, 0, 1, 2, 3)
            gmsh.model.occ.addBox(start, 0, 0, 1 if start == 1 else 2, 2, 3)
            gmsh.model.occ.synchronize()
            gmsh.write(step)
        finally:
            gmsh.finalize()
        return step

    return write
