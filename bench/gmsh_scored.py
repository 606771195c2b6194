"""Gmsh's volume mesh scored with tubemesh's own measures, for the bench scripts that compare with
Gmsh (quality_ceilings.py, table1.py): its tets written as MSH 4.1 and read by `tubemesh check`."""
import json
import subprocess

import gmsh


def scored_quality(tubemesh, out):
    """Writes the current Gmsh model's volume elements to `out` and returns the "quality" object
    of `tubemesh check --json` on it."""
    gmsh.model.addPhysicalGroup(3, [e[1] for e in gmsh.model.getEntities(3)])
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.write(out)
    checked = subprocess.run([tubemesh, "check", "--json", out], check=True, capture_output=True, text=True)
    return json.loads(checked.stdout)["quality"]
