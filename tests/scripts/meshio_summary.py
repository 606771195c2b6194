"""Reads a mesh file with meshio and prints what meshio sees, as JSON: point count, cell
counts per meshio cell type, names of cell data, cell sets and point sets with their sizes,
and for tubemesh's .vtu: how many cells carry each "group" value, the field data
(group name -> [id, dim]), the quality range and, per floating-point cell data array, the count
of NaN and of -1 values. A .vtm gives {"blocks": {"BLOCK/NAME": the
same for that block's .vtu}}.

usage: meshio_summary.py FILE.vtu|FILE.inp|FILE.vtm
"""
import collections
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

import meshio
from meshio.abaqus import _abaqus

# meshio 5.0 has no entry for Abaqus C3D5 (5-node pyramid) in its element table; this adds
# the name only, the file is still parsed by meshio's own reader.
_abaqus.abaqus_to_meshio_type.setdefault("C3D5", "pyramid")


def summary(path):
    mesh = meshio.read(path)
    cells = collections.Counter()
    for block in mesh.cells:
        cells[block.type] += len(block.data)
    out = {
        "points": len(mesh.points),
        "cells": dict(cells),
        "cell_data": sorted(mesh.cell_data),
        "cell_sets": sorted(mesh.cell_sets),
        "cell_set_sizes": {k: sum(len(ids) for ids in v) for k, v in mesh.cell_sets.items()},
        "point_sets": sorted(mesh.point_sets),
        "point_set_sizes": {k: len(v) for k, v in mesh.point_sets.items()},
        "field_data": {k: [int(x) for x in v] for k, v in mesh.field_data.items()},
    }
    if "group" in mesh.cell_data:
        groups = collections.Counter()
        for values in mesh.cell_data["group"]:
            groups.update(str(int(v)) for v in values)
        out["group_counts"] = dict(groups)
    # Per floating-point cell data array: how many values are NaN and how many are the -1 of
    # "no such measure".
    out["nan_counts"] = {}
    out["no_value_counts"] = {}
    for name, blocks in mesh.cell_data.items():
        values = [float(v) for block in blocks for v in block]
        if blocks and blocks[0].dtype.kind == "f":
            out["nan_counts"][name] = sum(1 for v in values if math.isnan(v))
            out["no_value_counts"][name] = sum(1 for v in values if v == -1)
    if "quality" in mesh.cell_data:
        values = [float(v) for block in mesh.cell_data["quality"] for v in block]
        finite = [v for v in values if not math.isnan(v)]
        out["quality_nan"] = len(values) - len(finite)
        if finite:
            out["quality_min"] = min(finite)
    return out


def main():
    path = sys.argv[1]
    if not path.endswith(".vtm"):
        print(json.dumps(summary(path)))
        return
    blocks = {}
    for block in ET.parse(path).getroot().iter("Block"):
        for data_set in block.iter("DataSet"):
            key = block.get("name") + "/" + data_set.get("name")
            blocks[key] = summary(os.path.join(os.path.dirname(path), data_set.get("file")))
    print(json.dumps({"blocks": blocks}))


if __name__ == "__main__":
    main()
