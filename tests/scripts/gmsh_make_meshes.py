"""Makes MSH 4.1 files with Gmsh itself, for testing tubemesh's reader on files it did not
write, and prints what each file holds as JSON: {file: {"elements": {type: count},
"physical": [[dim, tag, name], ...]}}.

  box_tets_ascii.msh, box_tets_binary.msh  tetrahedra; volume "block", surfaces "bottom",
                                           "walls" (nodes on many entities, sparse tags)
  box_hexes_binary.msh                     transfinite hexahedra and quads; "bricks", "skin"
  box_saveall.msh                          no physical groups: Gmsh saves points and lines too

usage: gmsh_make_meshes.py OUTDIR
"""
import json
import os
import sys

import gmsh


def box_with_groups(volume_name, surface_names):
    gmsh.model.occ.addBox(0, 0, 0, 1, 2, 0.5)
    gmsh.model.occ.synchronize()
    surfaces = [tag for _, tag in gmsh.model.getEntities(2)]
    bottom = [s for s in surfaces if gmsh.model.getBoundingBox(2, s)[5] < 1e-6]
    others = [s for s in surfaces if s not in bottom]
    groups = [(bottom, surface_names[0]), (others, surface_names[1])] if len(surface_names) == 2 else [
        (surfaces, surface_names[0])]
    for tag, (members, name) in enumerate(groups, start=1):
        gmsh.model.addPhysicalGroup(2, members, tag)
        gmsh.model.setPhysicalName(2, tag, name)
    gmsh.model.addPhysicalGroup(3, [1], 1)
    gmsh.model.setPhysicalName(3, 1, volume_name)


def summary():
    counts = {}
    for dim in (2, 3):
        types, tags, _ = gmsh.model.mesh.getElements(dim)
        for t, tg in zip(types, tags):
            counts[str(t)] = counts.get(str(t), 0) + len(tg)
    physical = [[d, t, gmsh.model.getPhysicalName(d, t)] for d, t in gmsh.model.getPhysicalGroups()]
    return {"elements": counts, "physical": physical}


def save(path, binary, save_all=False):
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.option.setNumber("Mesh.Binary", 1 if binary else 0)
    gmsh.option.setNumber("Mesh.SaveAll", 1 if save_all else 0)
    gmsh.write(path)


def main():
    out = sys.argv[1]
    result = {}
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)  # stdout carries the JSON only
    try:
        gmsh.model.add("tets")
        box_with_groups("block", ["bottom", "walls"])
        gmsh.option.setNumber("Mesh.MeshSizeMax", 0.25)
        gmsh.model.mesh.generate(3)
        for name, binary in (("box_tets_ascii.msh", False), ("box_tets_binary.msh", True)):
            save(os.path.join(out, name), binary)
            result[name] = summary()
        save(os.path.join(out, "box_saveall.msh"), False, save_all=True)

        gmsh.model.add("hexes")
        box_with_groups("bricks", ["skin"])
        for _, curve in gmsh.model.getEntities(1):
            gmsh.model.mesh.setTransfiniteCurve(curve, 4)
        for _, surface in gmsh.model.getEntities(2):
            gmsh.model.mesh.setTransfiniteSurface(surface)
            gmsh.model.mesh.setRecombine(2, surface)
        gmsh.model.mesh.setTransfiniteVolume(1)
        gmsh.model.mesh.generate(3)
        save(os.path.join(out, "box_hexes_binary.msh"), True)
        result["box_hexes_binary.msh"] = summary()
    finally:
        gmsh.finalize()
    print(json.dumps(result))


if __name__ == "__main__":
    main()
