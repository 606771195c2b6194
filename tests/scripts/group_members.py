"""Reads one mesh in its four formats - .msh with Gmsh, .vtu, the .vtm's blocks and .inp with
meshio - and prints, per format, which elements each group holds, so a test can check that
the formats agree element for element and not just in counts. JSON:

  {"msh"|"vtu"|"vtm"|"inp": {"dim:name": [element count, digest]},
   "points": {"vtu": max |difference| to the .msh nodes (-1: other count), "inp": the same},
   "nset_mismatch": [surfaces whose *NSET is not the set of their faces' nodes]}

An element is its node set (0-based indices, sorted, each once: a pyramid written as a brick
with its apex repeated is the same element): the same cell or face in every format. The
digest is a SHA-1 over a group's sorted elements. Groups without elements are left out.
  .msh  physical groups (Gmsh numbers nodes by tag; tubemesh writes tag = index + 1)
  .vtu  the volume cells: field data name -> [id, dim] and the "group" cell data
  .vtm  one .vtu per group, named in the index; a block's points are matched to the .msh's
        by their coordinates (the same doubles)
  .inp  element sets as meshio reads them; *SURFACE, TYPE=ELEMENT, which meshio skips, is
        read here: "element set, Sn" resolved with the face table of the Abaqus manual.
        The other element sets (KIND_*, EALL, the face sets NAME_Sk) are reported like the
        regions.

usage: group_members.py FILE.msh FILE.vtu FILE.inp [FILE.vtm]
"""
import collections
import hashlib
import json
import os
import sys
import xml.etree.ElementTree as ET

import gmsh
import meshio
import numpy as np
from meshio.abaqus import _abaqus

_abaqus.abaqus_to_meshio_type.setdefault("C3D5", "pyramid")  # as in meshio_summary.py

# Abaqus manual, solid element library: corner nodes (1-based) of faces S1, S2, ...
ABAQUS_FACES = {
    "C3D4": [(1, 2, 3), (1, 4, 2), (2, 4, 3), (3, 4, 1)],
    "C3D5": [(1, 2, 3, 4), (1, 5, 2), (2, 5, 3), (3, 5, 4), (4, 5, 1)],
    "C3D8": [(1, 2, 3, 4), (5, 8, 7, 6), (1, 5, 6, 2), (2, 6, 7, 3), (3, 7, 8, 4), (4, 8, 5, 1)],
}


def element(nodes):
    return tuple(sorted({int(v) for v in np.ravel(list(nodes))}))


def summarize(members):
    out = {}
    for key, elements in members.items():
        if elements:
            elements = sorted(elements)
            out[key] = [len(elements), hashlib.sha1(repr(elements).encode()).hexdigest()]
    return out


def read_msh(path):
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        gmsh.open(path)
        node_tags, coords, _ = gmsh.model.mesh.getNodes()
        order = np.argsort(node_tags)
        points = np.asarray(coords).reshape(-1, 3)[order]
        if list(np.asarray(node_tags)[order]) != list(range(1, len(node_tags) + 1)):
            raise SystemExit("node tags are not 1..n")
        members = collections.defaultdict(list)
        for dim, tag in gmsh.model.getPhysicalGroups():
            key = f"{dim}:{gmsh.model.getPhysicalName(dim, tag)}"
            for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
                types, _, nodes = gmsh.model.mesh.getElements(dim, entity)
                for t, n in zip(types, nodes):
                    per = gmsh.model.mesh.getElementProperties(t)[3]
                    for e in np.asarray(n, dtype=np.int64).reshape(-1, per):
                        members[key].append(element(int(v) - 1 for v in e))
    finally:
        gmsh.finalize()
    return summarize(members), points


def read_vtu(path):
    mesh = meshio.read(path)
    name_of = {(int(v[0]), int(v[1])): name for name, v in mesh.field_data.items()}
    members = collections.defaultdict(list)
    for block, group in zip(mesh.cells, mesh.cell_data["group"]):
        for cell, g in zip(block.data, group):
            members[f"3:{name_of[(int(g), 3)]}"].append(element(cell))
    return summarize(members), mesh.points


def read_vtm(path, msh_points):
    index = {tuple(p): i for i, p in enumerate(msh_points)}
    members = collections.defaultdict(list)
    folder = os.path.dirname(path)
    for block in ET.parse(path).getroot().iter("Block"):
        dim = 3 if block.get("name") == "volume" else 2
        for data_set in block.iter("DataSet"):
            name = data_set.get("name").split(" (")[0]  # "face_3 (top)": the group and its alias
            mesh = meshio.read(os.path.join(folder, data_set.get("file")))
            to_msh = [index[tuple(p)] for p in mesh.points]
            for cells in mesh.cells:
                for cell in cells.data:
                    members[f"{dim}:{name}"].append(element(to_msh[v] for v in cell))
    return summarize(members)


def inp_elements(path):
    """Element label -> (type, 0-based nodes), from the *ELEMENT blocks (labels and node
    numbers are 1-based in tubemesh's files: node label = index + 1)."""
    elements = {}
    etype = None
    with open(path) as f:
        for line in f:
            if line.startswith("*"):
                keyword = line.split(",")[0].strip().upper()
                etype = None
                if keyword == "*ELEMENT":
                    etype = line.upper().split("TYPE=")[1].split(",")[0].strip()
                continue
            if etype:
                values = [int(v) for v in line.split(",")]
                elements[values[0]] = (etype, [v - 1 for v in values[1:]])
    return elements


def inp_blocks(path, keyword):
    """(header line, data lines) of every *KEYWORD block; comments and other blocks skipped."""
    header, lines = None, []
    with open(path) as f:
        for line in f:
            if line.startswith("*"):
                if header:
                    yield header, lines
                header, lines = None, []
                if line.upper().startswith(keyword) and not line.startswith("**"):
                    header = line
            elif header:
                lines.append(line)
    if header:
        yield header, lines


def inp_element_sets(path):
    """Element set name -> labels, for the sets that list labels (the face sets NAME_Sk)."""
    sets = collections.defaultdict(list)
    for header, lines in inp_blocks(path, "*ELSET"):
        name = header.split("ELSET=")[1].split(",")[0].strip()
        for line in lines:
            if line[0].isdigit():
                sets[name] += [int(v) for v in line.split(",")]
    return sets


def inp_surfaces(path, elements):
    """*SURFACE, TYPE=ELEMENT: "element label or element set, Sn" lines."""
    sets = inp_element_sets(path)
    members = collections.defaultdict(list)
    for header, lines in inp_blocks(path, "*SURFACE"):
        if "TYPE=ELEMENT" not in header.upper():
            continue
        name = header.split("NAME=")[1].split(",")[0].strip()
        for line in lines:
            owner, face = (v.strip() for v in line.split(","))
            for label in sets[owner] if not owner.isdigit() else [int(owner)]:
                etype, nodes = elements[label]
                shape = etype.lstrip("D").rstrip("T")
                corners = ABAQUS_FACES[shape][int(face[1:]) - 1]
                members[name].append(element(nodes[c - 1] for c in corners))
    return members


def read_inp(path):
    mesh = meshio.read(path)
    members = collections.defaultdict(list)
    for name, per_block in mesh.cell_sets.items():
        for block, ids in zip(mesh.cells, per_block):
            for i in ids:
                members[f"3:{name}"].append(element(block.data[i]))
    surfaces = inp_surfaces(path, inp_elements(path))
    nset_mismatch = []
    for name, faces in surfaces.items():
        members[f"2:{name}"] = faces
        face_nodes = sorted({n for face in faces for n in face})
        if sorted(int(v) for v in mesh.point_sets.get(name, [])) != face_nodes:
            nset_mismatch.append(name)
    return summarize(members), mesh.points, nset_mismatch


def main():
    msh, msh_points = read_msh(sys.argv[1])
    vtu, vtu_points = read_vtu(sys.argv[2])
    inp, inp_points, nset_mismatch = read_inp(sys.argv[3])
    vtm = read_vtm(sys.argv[4], msh_points) if len(sys.argv) > 4 else {}

    def difference(points):
        if points.shape != msh_points.shape:
            return -1.0  # JSON has no infinity
        return float(np.max(np.abs(points - msh_points))) if len(points) else 0.0

    print(json.dumps({
        "msh": msh,
        "vtu": vtu,
        "vtm": vtm,
        "inp": inp,
        "points": {"vtu": difference(vtu_points), "inp": difference(inp_points)},
        "nset_mismatch": nset_mismatch,
    }))


if __name__ == "__main__":
    main()
