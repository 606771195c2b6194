"""Runs CalculiX (Debian's ccx) on a tubemesh .inp and prints what it computed, as JSON.

  calculix_run.py patch MESH.inp DIR
      Steady heat conduction with T = x + 2y + 3z fixed on every boundary node (every node
      set of the file but NALL and those of interface groups, JOINT_*, which lie inside an
      assembly). Linear elements reproduce a linear field exactly, so any misread coordinate,
      mis-numbered element or hanging node (a joint whose sides do not match) shows as an error.
      -> {"nodes", "boundary_nodes", "max_error", "max_abs_t", "relative_error"}
  calculix_run.py thermal MESH.inp DIR PIPE TOP boundary|film
      Steady heat conduction, the pipe wall at 10 and the top at 25: as fixed temperatures on
      the node sets PIPE and TOP, or (film) the top fixed and a film of sink temperature 10 on
      the pipe through the element-face sets PIPE_S1..PIPE_S6 (*FILM takes "set, Fk").
      -> {"nodes", "t_min", "t_max", "pipe_t_min", "pipe_t_max", "film_lines"}
  calculix_run.py gravity MESH.inp DIR BOTTOM
      Linear statics under gravity (E 30 GPa, Poisson 0, density 2400 kg/m3, g 9.81), the
      node set BOTTOM fixed: a column of height H (the z extent) whose top moves by
      rho g H^2 / (2 E).
      -> {"nodes", "height", "max_displacement", "estimate", "ratio"}
  calculix_run.py deck DECK.inp MESH.inp DIR
      Runs DECK as written, with MESH beside it under its own name, and reports the
      temperatures it printed: {"nodes", "t_min", "t_max"}.

Temperatures and displacements are read from the .dat file (*NODE PRINT, 7 digits). The
work goes to DIR, which must exist. Exit status 1 with the reason on stderr when ccx fails.
"""
import json
import math
import os
import re
import shutil
import sys

from ccx_files import dat_blocks, read_inp, run_ccx


def parse_inp(path):
    """Node label -> (x, y, z); node set name (upper case) -> labels; element set names."""
    nodes, _, node_sets, element_sets = read_inp(path)
    return nodes, node_sets, set(element_sets)


def node_values(directory, job):
    """Runs ccx on DIR/JOB.inp: node -> values of the last *NODE PRINT block (one value for NT,
    three for U)."""
    path = run_ccx(directory, job)
    values = {}
    for _, block in dat_blocks(path):
        values.update(block)
    if not values:
        sys.exit(f"no node values in {path}")
    return values


def place(path, directory, name):
    """`path` as DIR/name for the deck to include (a copy unless it is that file already)."""
    target = os.path.join(directory, name)
    if not (os.path.exists(target) and os.path.samefile(path, target)):
        shutil.copy(path, target)


def heat_deck(mesh, loads):
    return (f"*INCLUDE, INPUT={mesh}\n"
            "*MATERIAL, NAME=CONCRETE\n*CONDUCTIVITY\n2.5\n"
            "*SOLID SECTION, ELSET=EALL, MATERIAL=CONCRETE\n"
            "*STEP\n*HEAT TRANSFER, STEADY STATE\n" + loads +
            "*NODE PRINT, NSET=NALL\nNT\n*END STEP\n")


def write(directory, name, text):
    with open(os.path.join(directory, name), "w") as f:
        f.write(text)


def patch(mesh_path, directory):
    nodes, node_sets, _ = parse_inp(mesh_path)
    fixed = [name for name in node_sets if name != "NALL" and "JOINT_" not in name]
    boundary = sorted({n for name in fixed for n in node_sets[name]})
    exact = {n: x + 2 * y + 3 * z for n, (x, y, z) in nodes.items()}
    lines = "".join(f"{n}, 11, 11, {exact[n]:.14g}\n" for n in boundary)
    place(mesh_path, directory, "mesh.inp")
    write(directory, "patch.inp", heat_deck("mesh.inp", "*BOUNDARY\n" + lines))
    t = node_values(directory, "patch")
    missing = set(nodes) - set(t)
    if missing:
        sys.exit(f"{len(missing)} nodes have no temperature")
    error = max(abs(t[n][0] - exact[n]) for n in nodes)
    largest = max(abs(v) for v in exact.values())
    return {"nodes": len(nodes), "boundary_nodes": len(boundary), "max_error": error, "max_abs_t": largest,
            "relative_error": error / largest}


def thermal(mesh_path, directory, pipe, top, variant):
    nodes, node_sets, element_sets = parse_inp(mesh_path)
    pipe, top = pipe.upper(), top.upper()
    loads = f"*BOUNDARY\n{top}, 11, 11, 25.\n"
    film_lines = 0
    if variant == "boundary":
        loads += f"*BOUNDARY\n{pipe}, 11, 11, 10.\n"
    else:
        faces = sorted(s for s in element_sets if re.fullmatch(re.escape(pipe) + r"_S[1-6]", s))
        film_lines = len(faces)
        loads += "*FILM\n" + "".join(f"{s}, F{s[-1]}, 10., 1.E8\n" for s in faces)
    place(mesh_path, directory, "mesh.inp")
    write(directory, "thermal.inp", heat_deck("mesh.inp", loads))
    t = node_values(directory, "thermal")
    pipe_t = [t[n][0] for n in node_sets[pipe]]
    return {"nodes": len(t), "t_min": min(v[0] for v in t.values()), "t_max": max(v[0] for v in t.values()),
            "pipe_t_min": min(pipe_t), "pipe_t_max": max(pipe_t), "film_lines": film_lines}


def gravity(mesh_path, directory, bottom):
    nodes, _, _ = parse_inp(mesh_path)
    young, density, g = 30e9, 2400.0, 9.81
    zs = [p[2] for p in nodes.values()]
    height = max(zs) - min(zs)
    place(mesh_path, directory, "mesh.inp")
    write(directory, "gravity.inp",
          "*INCLUDE, INPUT=mesh.inp\n"
          f"*MATERIAL, NAME=CONCRETE\n*ELASTIC\n{young:.6g}, 0.\n*DENSITY\n{density}\n"
          "*SOLID SECTION, ELSET=EALL, MATERIAL=CONCRETE\n"
          f"*STEP\n*STATIC\n*BOUNDARY\n{bottom.upper()}, 1, 3\n"
          f"*DLOAD\nEALL, GRAV, {g}, 0., 0., -1.\n"
          "*NODE PRINT, NSET=NALL\nU\n*END STEP\n")
    u = node_values(directory, "gravity")
    largest = max(math.sqrt(sum(c * c for c in v[:3])) for v in u.values())
    estimate = density * g * height ** 2 / (2 * young)
    return {"nodes": len(u), "height": height, "max_displacement": largest, "estimate": estimate,
            "ratio": largest / estimate}


def deck(deck_path, mesh_path, directory):
    place(mesh_path, directory, os.path.basename(mesh_path))
    place(deck_path, directory, "deck.inp")
    t = node_values(directory, "deck")
    return {"nodes": len(t), "t_min": min(v[0] for v in t.values()), "t_max": max(v[0] for v in t.values())}


def main():
    mode, args = sys.argv[1], sys.argv[2:]
    result = {"patch": patch, "thermal": thermal, "gravity": gravity, "deck": deck}[mode](*args)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
