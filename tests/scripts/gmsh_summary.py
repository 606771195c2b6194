"""Opens a mesh file with Gmsh's own reader and prints what Gmsh sees, as JSON:
element counts per Gmsh type, node count, physical groups [dim, tag, name], and per physical
group "dim:name" -> [entities, elements].

usage: gmsh_summary.py FILE.msh
"""
import json
import sys

import gmsh


def group_sizes(dim, tag):
    entities = gmsh.model.getEntitiesForPhysicalGroup(dim, tag)
    elements = 0
    for e in entities:
        _, tags, _ = gmsh.model.mesh.getElements(dim, e)
        elements += sum(len(t) for t in tags)
    return [len(entities), elements]


def main():
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)  # stdout carries the JSON only
    try:
        gmsh.open(sys.argv[1])
        types, tags, _ = gmsh.model.mesh.getElements()
        counts = {str(t): len(tg) for t, tg in zip(types, tags)}
        nodes = len(gmsh.model.mesh.getNodes()[0])
        physical = [[d, t, gmsh.model.getPhysicalName(d, t)] for d, t in gmsh.model.getPhysicalGroups()]
        groups = {f"{d}:{name}": group_sizes(d, t) for d, t, name in physical}
    finally:
        gmsh.finalize()
    print(json.dumps({"elements": counts, "nodes": nodes, "physical": physical, "groups": groups}))


if __name__ == "__main__":
    main()
