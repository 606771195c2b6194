"""Runs CalculiX (Debian's ccx) steps other than steady heat conduction on a tubemesh .inp and
prints what it computed, as JSON (the mesh is read with calculix_run.parse_inp).

  calculix_steps.py coupled MESH.inp DIR LEFT UPSTREAM BOTTOM
      A steady *COUPLED TEMPERATURE-DISPLACEMENT step (E 30 GPa, Poisson 0, expansion 1e-5,
      conductivity 2.5): the block starts at 20, every boundary node is held at 30, and the
      faces LEFT (-x), UPSTREAM (-y) and BOTTOM (-z) slide in their planes. The exact answer is
      free expansion, T = 30 and u = 1e-4 (x - x0, y - y0, z - z0), which linear elements
      reproduce: a coupled patch test of the temperature and displacement at every node.
      -> {"nodes", "t_error", "max_displacement", "u_error", "relative_u_error"}
  calculix_steps.py lifts MESH.inp DIR LOWER UPPER
      Construction in two lifts, transient heat transfer (conductivity 2.5, density 2400,
      specific heat 900, everything at 20 to start): step 1 removes the element set UPPER
      (*MODEL CHANGE, TYPE=ELEMENT, REMOVE) and cools LOWER's top, the element-face sets
      LOWER_top_S1..S6, by a film (sink 5, coefficient 10) for a day; step 2 adds UPPER again and
      moves the film to UPPER_top for a day. Reports per step the temperatures on LOWER's top,
      on UPPER's nodes that LOWER does not have, and on UPPER's top.
      -> {"film_lines": [step 1, step 2], "steps": [{"lower_top": [min, max], "upper_only": [min, max],
          "upper_top": [min, max]}, ...]}

The work goes to DIR, which must exist. Exit status 1 with the reason on stderr when ccx fails.
"""
import json
import sys

from calculix_run import parse_inp, place, write
from ccx_files import dat_blocks, read_inp, run_ccx


def blocks_by_kind(directory, job):
    """Runs ccx on DIR/JOB.inp: node -> values per kind of *NODE PRINT block ("temperatures",
    "displacements"), the last block of each kind winning."""
    blocks = {}
    for title, values in dat_blocks(run_ccx(directory, job)):
        blocks.setdefault(title.split()[0], {}).update(values)
    return blocks


def coupled(mesh_path, directory, left, upstream, bottom):
    nodes, node_sets, _ = parse_inp(mesh_path)
    boundary = sorted({n for name, members in node_sets.items() if name != "NALL" for n in members})
    alpha, rise = 1e-5, 10.0
    x0, y0, z0 = (min(p[i] for p in nodes.values()) for i in range(3))
    place(mesh_path, directory, "mesh.inp")
    write(directory, "coupled.inp",
          "*INCLUDE, INPUT=mesh.inp\n"
          "*MATERIAL, NAME=CONCRETE\n*ELASTIC\n30.E9, 0.\n*EXPANSION, ZERO=20.\n1.E-5\n"
          "*CONDUCTIVITY\n2.5\n*DENSITY\n2400.\n*SPECIFIC HEAT\n900.\n"
          "*SOLID SECTION, ELSET=EALL, MATERIAL=CONCRETE\n"
          "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n"
          "*STEP\n*COUPLED TEMPERATURE-DISPLACEMENT, STEADY STATE\n1., 1.\n"
          f"*BOUNDARY\n{left.upper()}, 1, 1\n{upstream.upper()}, 2, 2\n{bottom.upper()}, 3, 3\n"
          "*BOUNDARY\n" + "".join(f"{n}, 11, 11, 30.\n" for n in boundary) +
          "*NODE PRINT, NSET=NALL\nNT\n*NODE PRINT, NSET=NALL\nU\n*END STEP\n")
    r = blocks_by_kind(directory, "coupled")
    t, u = r.get("temperatures", {}), r.get("displacements", {})
    if set(t) != set(nodes) or set(u) != set(nodes):
        sys.exit(f"ccx printed {len(t)} temperatures and {len(u)} displacements for {len(nodes)} nodes")
    exact = {n: (alpha * rise * (x - x0), alpha * rise * (y - y0), alpha * rise * (z - z0))
             for n, (x, y, z) in nodes.items()}
    largest = max(max(abs(c) for c in e) for e in exact.values())
    u_error = max(abs(u[n][i] - exact[n][i]) for n in nodes for i in range(3))
    return {"nodes": len(nodes), "t_error": max(abs(t[n][0] - 30.0) for n in nodes),
            "max_displacement": max(max(abs(c) for c in v[:3]) for v in u.values()), "u_error": u_error,
            "relative_u_error": u_error / largest}


def element_sets(path):
    """Element set name (upper case) -> the node labels of its elements."""
    _, elements, _, sets = read_inp(path)
    return {n: {v for e in members for v in elements[e][1]} for n, members in sets.items()}


def films(element_set_names, surface):
    faces = sorted(s for s in element_set_names if s.startswith(surface + "_S") and s[-1] in "123456")
    return faces, "".join(f"{s}, F{s[-1]}, 5., 10.\n" for s in faces)


def temperature_blocks(directory, job):
    """Runs ccx on DIR/JOB.inp: the printed temperature blocks of the .dat file, in order (one
    per increment here)."""
    return [{n: v[0] for n, v in values.items()} for title, values in dat_blocks(run_ccx(directory, job))
            if title.split()[0] == "temperatures"]


def lifts(mesh_path, directory, lower, upper):
    lower, upper = lower.upper(), upper.upper()
    _, node_sets, element_set_names = parse_inp(mesh_path)
    nodes_of = element_sets(mesh_path)
    lower_faces, lower_film = films(element_set_names, lower + "_TOP")
    upper_faces, upper_film = films(element_set_names, upper + "_TOP")
    if not lower_faces or not upper_faces:
        sys.exit(f"no element-face sets {lower}_TOP_Sk or {upper}_TOP_Sk in {mesh_path}")
    place(mesh_path, directory, "mesh.inp")
    write(directory, "lifts.inp",
          "*INCLUDE, INPUT=mesh.inp\n"
          "*MATERIAL, NAME=CONCRETE\n*CONDUCTIVITY\n2.5\n*DENSITY\n2400.\n*SPECIFIC HEAT\n900.\n"
          "*SOLID SECTION, ELSET=EALL, MATERIAL=CONCRETE\n"
          "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n"
          "*STEP\n*HEAT TRANSFER, DIRECT\n43200., 86400.\n"
          f"*MODEL CHANGE, TYPE=ELEMENT, REMOVE\n{upper}\n"
          "*FILM\n" + lower_film +
          "*NODE PRINT, NSET=NALL\nNT\n*END STEP\n"
          "*STEP\n*HEAT TRANSFER, DIRECT\n43200., 86400.\n"
          f"*MODEL CHANGE, TYPE=ELEMENT, ADD\n{upper}\n"
          "*FILM, OP=NEW\n" + upper_film +
          "*NODE PRINT, NSET=NALL\nNT\n*END STEP\n")
    blocks = temperature_blocks(directory, "lifts")
    # The last block of each step: two increments a step.
    if len(blocks) != 4:
        sys.exit(f"expected 4 temperature blocks (2 steps x 2 increments), found {len(blocks)}")
    groups = {"lower_top": node_sets[lower + "_TOP"], "upper_only": nodes_of[upper] - nodes_of[lower],
              "upper_top": node_sets[upper + "_TOP"]}
    steps = []
    for t in (blocks[1], blocks[3]):
        steps.append({k: [min(t[n] for n in members), max(t[n] for n in members)] for k, members in groups.items()})
    return {"film_lines": [len(lower_faces), len(upper_faces)], "steps": steps}


def main():
    mode, args = sys.argv[1], sys.argv[2:]
    result = {"coupled": coupled, "lifts": lifts}[mode](*args)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
