"""Opens tubemesh's VTK files with VTK itself (the library ParaView reads them with) and prints
what it sees, as JSON.

  vtk_check.py FILE.vtu
      {"cells": {vtk cell type: count}, "arrays": [cell data names],
       "differences": {measure: largest |ours - theirs| over the cells it rates}}
      vtkMeshQuality computes Verdict's tet scaled Jacobian and aspect ratio and the hex scaled
      Jacobian; ours are the cell data scaled_jacobian and aspect_ratio. Verdict's tet "minimum
      angle" takes the supplement at two of the six edges (its face normals are not oriented
      alike), so min_dihedral is checked against the six angles computed here in another way:
      at edge ij, the angle between the other two vertices' offsets perpendicular to the edge.
  vtk_check.py FILE.vtm
      {"blocks": {"BLOCK/NAME": cell count}}, the names as VTK's multiblock reader gives them.
"""
import json
import math
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def quality(grid, setup, name):
    q = vtk.vtkMeshQuality()
    q.SetInputData(grid)
    setup(q)
    q.Update()
    return vtk_to_numpy(q.GetOutput().GetCellData().GetArray("Quality"))


def check_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    types = vtk_to_numpy(grid.GetCellTypesArray()) if grid.GetNumberOfCells() else []
    cells = {}
    for t in types:
        cells[str(int(t))] = cells.get(str(int(t)), 0) + 1
    data = grid.GetCellData()
    arrays = sorted(data.GetArrayName(i) for i in range(data.GetNumberOfArrays()))
    measures = {
        "tet scaled_jacobian": (vtk.VTK_TETRA, "scaled_jacobian", lambda q: q.SetTetQualityMeasureToScaledJacobian()),
        "tet aspect_ratio": (vtk.VTK_TETRA, "aspect_ratio", lambda q: q.SetTetQualityMeasureToAspectRatio()),
        "hex scaled_jacobian": (vtk.VTK_HEXAHEDRON, "scaled_jacobian",
                                lambda q: q.SetHexQualityMeasureToScaledJacobian()),
    }
    differences = {}
    for key, (cell_type, ours, setup) in measures.items():
        theirs = quality(grid, setup, key)
        mine = vtk_to_numpy(data.GetArray(ours))
        worst, rated = 0.0, 0
        for t, a, b in zip(types, mine, theirs):
            if t == cell_type:
                rated += 1
                worst = max(worst, abs(float(a) - float(b)))
        differences[key] = worst if rated else None
    differences["tet min_dihedral"] = dihedral_difference(grid, types, vtk_to_numpy(data.GetArray("min_dihedral")))
    return {"cells": cells, "arrays": arrays, "differences": differences}


def dihedral_difference(grid, types, ours):
    points = vtk_to_numpy(grid.GetPoints().GetData())
    connectivity = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    offsets = vtk_to_numpy(grid.GetCells().GetOffsetsArray())[:-1]
    tets = np.nonzero(types == vtk.VTK_TETRA)[0]
    if len(tets) == 0:
        return None
    p = points[connectivity[offsets[tets][:, None] + np.arange(4)]]  # tets x 4 corners x 3
    smallest = np.full(len(tets), 180.0)
    for i, j, k, l in ((0, 1, 2, 3), (0, 2, 1, 3), (0, 3, 1, 2), (1, 2, 0, 3), (1, 3, 0, 2), (2, 3, 0, 1)):
        e = p[:, j] - p[:, i]
        e /= np.linalg.norm(e, axis=1)[:, None]
        u = p[:, k] - p[:, i]
        v = p[:, l] - p[:, i]
        u -= np.sum(u * e, axis=1)[:, None] * e
        v -= np.sum(v * e, axis=1)[:, None] * e
        angle = np.degrees(np.arctan2(np.linalg.norm(np.cross(u, v), axis=1), np.sum(u * v, axis=1)))
        smallest = np.minimum(smallest, angle)
    return float(np.max(np.abs(smallest - ours[tets])))


def check_vtm(path):
    reader = vtk.vtkXMLMultiBlockDataReader()
    reader.SetFileName(path)
    reader.Update()
    top = reader.GetOutput()
    blocks = {}
    for i in range(top.GetNumberOfBlocks()):
        outer = top.GetMetaData(i).Get(vtk.vtkCompositeDataSet.NAME())
        inner = top.GetBlock(i)
        for j in range(inner.GetNumberOfBlocks()):
            name = inner.GetMetaData(j).Get(vtk.vtkCompositeDataSet.NAME())
            blocks[f"{outer}/{name}"] = inner.GetBlock(j).GetNumberOfCells()
    return {"blocks": blocks}


def main():
    path = sys.argv[1]
    print(json.dumps(check_vtm(path) if path.endswith(".vtm") else check_vtu(path)))


if __name__ == "__main__":
    main()
