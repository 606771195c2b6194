"""Opens a mesh file with Gmsh's own reader and prints what Gmsh sees, as JSON:
element counts per Gmsh type, node count, physical groups [dim, tag, name].

usage: gmsh_summary.py FILE.msh
"""
import json
import sys

import gmsh


def main():
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)  # stdout carries the JSON only
    try:
        gmsh.open(sys.argv[1])
        types, tags, _ = gmsh.model.mesh.getElements()
        counts = {str(t): len(tg) for t, tg in zip(types, tags)}
        nodes = len(gmsh.model.mesh.getNodes()[0])
        physical = [[d, t, gmsh.model.getPhysicalName(d, t)] for d, t in gmsh.model.getPhysicalGroups()]
    finally:
        gmsh.finalize()
    print(json.dumps({"elements": counts, "nodes": nodes, "physical": physical}))


if __name__ == "__main__":
    main()
