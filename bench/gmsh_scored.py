"""Gmsh all-tet meshes of a CAD file scored with tubemesh's own measures, for the bench scripts
that compare with Gmsh (quality_ceilings.py, table1.py): the tets written as MSH 4.1 and read by
`tubemesh check`. gmsh.initialize() is the caller's."""
import json
import subprocess

import gmsh


def scored_gmsh_mesh(tubemesh, step, out, numbers, strings=None):
    """Meshes `step` with Gmsh under the options `numbers` (name -> number) and `strings` (name ->
    text, set before the import), writes its tets to `out` and returns the "quality" object of
    `tubemesh check --json` on them."""
    gmsh.clear()
    for name, value in (strings or {}).items():
        gmsh.option.setString(name, value)
    gmsh.model.occ.importShapes(step)
    gmsh.model.occ.synchronize()
    for name, value in numbers.items():
        gmsh.option.setNumber(name, value)
    gmsh.model.mesh.generate(3)
    gmsh.model.addPhysicalGroup(3, [e[1] for e in gmsh.model.getEntities(3)])
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.write(out)
    checked = subprocess.run([tubemesh, "check", "--json", out], check=True, capture_output=True, text=True)
    return json.loads(checked.stdout)["quality"]
