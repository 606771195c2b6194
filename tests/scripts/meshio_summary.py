"""Reads a mesh file with meshio and prints what meshio sees, as JSON: point count, cell
counts per meshio cell type, names of cell data, cell sets and point sets, and how many
cells carry each "region" value (when the file has that cell data).

usage: meshio_summary.py FILE.vtu|FILE.inp
"""
import collections
import json
import sys

import meshio
from meshio.abaqus import _abaqus

# meshio 5.0 has no entry for Abaqus C3D5 (5-node pyramid) in its element table; this adds
# the name only, the file is still parsed by meshio's own reader.
_abaqus.abaqus_to_meshio_type.setdefault("C3D5", "pyramid")


def main():
    mesh = meshio.read(sys.argv[1])
    cells = collections.Counter()
    for block in mesh.cells:
        cells[block.type] += len(block.data)
    out = {
        "points": len(mesh.points),
        "cells": dict(cells),
        "cell_data": sorted(mesh.cell_data),
        "cell_sets": sorted(mesh.cell_sets),
        "point_sets": sorted(mesh.point_sets),
    }
    if "region" in mesh.cell_data:
        regions = collections.Counter()
        for values in mesh.cell_data["region"]:
            regions.update(str(int(v)) for v in values)
        out["region_counts"] = dict(regions)
    if "quality" in mesh.cell_data:
        out["quality_min"] = min(float(v.min()) for v in mesh.cell_data["quality"] if len(v))
    print(json.dumps(out))


if __name__ == "__main__":
    main()
