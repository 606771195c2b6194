"""The water networks of `tubemesh mesh --pipe-network` (X.inp and X.films.inp), checked as they
are written and as CalculiX (Debian's ccx) solves them; prints what it found as JSON.

  calculix_network.py structure MESH.inp RADIUS
      Per pipe k: every wall face (the element faces of the sets pipe_k_S1..S6) has exactly one
      *FILM line in MESH.films.inp and no film line names another face; every water node lies
      on the centre line (its distance to the nearest node of pipe_k is RADIUS within 1 %); the
      D elements of pipe_k_water are one chain from pipe_k_water_in to pipe_k_water_out, with
      an inlet element (0, m, T_in) and an outlet element (T_out, m, 0).
      -> {"pipes": {name: {"faces", "film_lines", "missing", "extra", "repeated", "water_nodes",
          "worst_radius_error", "chain", "segments"}}}
  calculix_network.py fixed MESH.inp DIR T_CONCRETE T_IN MASS_FLOW H LENGTH DIAMETER
      Steady heat transfer, every concrete node held at T_CONCRETE, water at T_IN entering
      pipe_1 at MASS_FLOW: the outlet temperature against
      T_c - (T_c - T_in) exp(-h pi D L / (m c_p)).
      -> {"t_out", "t_formula", "error_of_t_out", "error_of_rise"}
  calculix_network.py balance MESH.inp DIR T_FIXED T_IN MASS_FLOW
      Steady heat transfer, the nodes at the largest z held at T_FIXED, water at T_IN entering
      pipe_1: the heat the water carries away, m c_p (T_out - T_in), against the heat through
      the wall faces (h times the integral of T - T_sink over every film face, 2 x 2 Gauss points
      as CalculiX integrates) and against the heat through the fixed nodes (their reactions).
      -> {"t_out", "water_heat", "wall_heat", "fixed_heat", "error_wall", "error_fixed"}
  calculix_network.py mirror FORWARD.inp REVERSED.inp DIR T_FIXED T_IN MASS_FLOW
      The same steady problem (top and bottom at T_FIXED) on one block with the flow one way and
      the other: each water temperature node of one run against the node of the other at the
      mirrored place (about the middle of the pipe's axis, the x extent of its nodes).
      -> {"nodes", "matched", "max_difference", "rise", "error", "inlets" (x of each run's _water_in)}
  calculix_network.py transient DECK.inp MESH.inp DIR
      Runs DECK as written, MESH and its films file beside it under their own names, and reads
      every "temperatures for set PIPE_<k>_WATER_OUT" block it printed.
      -> {"times": [...], "outlets": {"pipe_1": [...], ...}} (one temperature per time)

Water: c_p 4186 J/(kg K), concrete: conductivity 2.5 W/(m K). Exit status 1 with the reason on
stderr when ccx fails.
"""
import json
import math
import os
import re
import shutil
import sys

import numpy

from ccx_files import dat_blocks, read_inp, run_ccx

CP = 4186.0


def films_of(mesh_path):
    """(element, face number, sink node, h) per *FILM line of MESH.films.inp."""
    films = []
    with open(mesh_path[:-4] + ".films.inp") as f:
        for line in f:
            m = re.match(r"\s*(\d+),\s*F(\d)FC,\s*(\d+),\s*(\S+)", line)
            if m:
                films.append((int(m[1]), int(m[2]), int(m[3]), float(m[4])))
    return films


def pipe_names(elsets):
    return sorted({m[1] for s in elsets for m in [re.fullmatch(r"(PIPE_\d+)_WATER", s)] if m},
                  key=lambda n: int(n.split("_")[1]))


def chain(name, elements, elsets, nsets):
    """The water nodes from _water_in to _water_out through pipe's D elements, or an error string."""
    members = [elements[e][1] for e in elsets[name + "_WATER"]]
    if any(elements[e][0] != "D" for e in elsets[name + "_WATER"]):
        return None, "not all D elements"
    inlets = [m for m in members if m[0] == 0]
    outlets = [m for m in members if m[2] == 0]
    if len(inlets) != 1 or len(outlets) != 1:
        return None, f"{len(inlets)} inlet and {len(outlets)} outlet elements"
    by_first = {}
    for m in members:
        if m[0] != 0:
            if m[0] in by_first:
                return None, f"node {m[0]} starts two elements"
            by_first[m[0]] = m
    if [inlets[0][2]] != nsets[name + "_WATER_IN"]:
        return None, "the inlet element does not end at _water_in"
    node, path, used = inlets[0][2], [inlets[0][2]], 1
    while node in by_first:
        m = by_first.pop(node)
        used += 1
        node = m[2]
        if node == 0:
            break
        path.append(node)
    if node != 0 or used != len(members) or by_first:
        return None, "the D elements are not one chain"
    if [path[-1]] != nsets[name + "_WATER_OUT"]:
        return None, "the chain does not end at _water_out"
    return path, "one chain"


def structure(mesh_path, radius):
    nodes, elements, nsets, elsets = read_inp(mesh_path)
    radius = float(radius)
    films = films_of(mesh_path)
    film_faces = {}
    for element, face, sink, _ in films:
        film_faces[(element, face)] = film_faces.get((element, face), 0) + 1
    out = {}
    water = set(nsets.get("WATER", []))
    for name in pipe_names(elsets):
        faces = {(e, int(s[-1])) for s in elsets if re.fullmatch(name + r"_S[1-6]", s) for e in elsets[s]}
        own = set(nsets[name + "_WATER"])
        pipe_film_faces = {(e, f) for (e, f, sink, _) in films if sink in own}
        wall = numpy.array([nodes[n] for n in nsets[name]])
        worst = 0.0
        for n in nsets[name + "_WATER"]:
            nearest = numpy.sqrt(((wall - numpy.array(nodes[n])) ** 2).sum(axis=1).min())
            worst = max(worst, abs(float(nearest) - radius) / radius)
        path, verdict = chain(name, elements, elsets, nsets)
        out[name.lower()] = {
            "faces": len(faces),
            "film_lines": sum(1 for (e, f, sink, _) in films if sink in own),
            "missing": len(faces - set(film_faces)),
            "extra": len(pipe_film_faces - faces),
            "repeated": sum(1 for k in faces if film_faces.get(k, 0) > 1),
            "water_nodes": len(nsets[name + "_WATER"]),
            "in_nall": len(own & set(nsets["NALL"])),
            "outside_water": len(own - water),
            "worst_radius_error": worst,
            "chain": verdict,
            "segments": len(path) - 1 if path else 0,
        }
    return {"pipes": out}


def titled_blocks(directory, job):
    """Runs ccx on DIR/JOB.inp: block title ("temperatures WATER", ...) -> node -> values (the
    last block of each title)."""
    blocks = {}
    for title, values in dat_blocks(run_ccx(directory, job)):
        m = re.match(r"(.+?) for set (\S+) and time", title)
        if m:
            blocks[f"{m[1]} {m[2]}"] = values
    return blocks


def place(mesh_path, directory):
    for suffix in (".inp", ".films.inp"):
        shutil.copy(mesh_path[:-4] + suffix, os.path.join(directory, "mesh" + suffix))


def deck(directory, job, boundary, mass_flow, outputs):
    text = ("*INCLUDE, INPUT=mesh.inp\n"
            "*MATERIAL, NAME=CONCRETE\n*CONDUCTIVITY\n2.5\n"
            "*SOLID SECTION, ELSET=EALL, MATERIAL=CONCRETE\n"
            f"*MATERIAL, NAME=WATER\n*FLUID CONSTANTS\n{CP}, 1.E-3, 293.\n"
            "*FLUID SECTION, ELSET=WATER, MATERIAL=WATER\n"
            "*PHYSICAL CONSTANTS, ABSOLUTE ZERO=-273.15\n"
            "*STEP\n*HEAT TRANSFER, STEADY STATE\n"
            f"*BOUNDARY\n{boundary}PIPE_1_WATER_FLOW, 1, 1, {mass_flow}\n"
            "*INCLUDE, INPUT=mesh.films.inp\n" + outputs + "*END STEP\n")
    with open(os.path.join(directory, job + ".inp"), "w") as f:
        f.write(text)
    return titled_blocks(directory, job)


def fixed(mesh_path, directory, t_concrete, t_in, mass_flow, h, length, diameter):
    t_c, t_in, m, h, length, d = map(float, (t_concrete, t_in, mass_flow, h, length, diameter))
    nodes, _, nsets, _ = read_inp(mesh_path)
    place(mesh_path, directory)
    boundary = f"NALL, 11, 11, {t_c}\nPIPE_1_WATER_IN, 11, 11, {t_in}\n"
    r = deck(directory, "fixed", boundary, m, "*NODE PRINT, NSET=WATER\nNT\n")
    t = r["temperatures WATER"]
    t_out = t[nsets["PIPE_1_WATER_OUT"][0]][0]
    formula = t_c - (t_c - t_in) * math.exp(-h * math.pi * d * length / (m * CP))
    return {"t_out": t_out, "t_formula": formula, "error_of_t_out": abs(t_out - formula) / abs(formula),
            "error_of_rise": abs(t_out - formula) / abs(formula - t_in)}


def gauss_film_heat(nodes, element_nodes, face, h, t, t_sink):
    """h times the integral of (T - T_sink) over face `face` (1-6) of a C3D8, 2 x 2 Gauss points."""
    corners = {1: (0, 1, 2, 3), 2: (4, 5, 6, 7), 3: (0, 1, 5, 4), 4: (1, 2, 6, 5), 5: (2, 3, 7, 6), 6: (3, 0, 4, 7)}[face]
    quad = [element_nodes[i] for i in corners]
    g = 1 / math.sqrt(3)
    total = 0.0
    for xi in (-g, g):
        for eta in (-g, g):
            shape = [(1 - xi) * (1 - eta) / 4, (1 + xi) * (1 - eta) / 4, (1 + xi) * (1 + eta) / 4,
                     (1 - xi) * (1 + eta) / 4]
            d_xi = [-(1 - eta) / 4, (1 - eta) / 4, (1 + eta) / 4, -(1 + eta) / 4]
            d_eta = [-(1 - xi) / 4, -(1 + xi) / 4, (1 + xi) / 4, (1 - xi) / 4]
            a = [sum(d_xi[i] * nodes[quad[i]][c] for i in range(4)) for c in range(3)]
            b = [sum(d_eta[i] * nodes[quad[i]][c] for i in range(4)) for c in range(3)]
            jac = math.dist((0, 0, 0), (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]))
            temperature = sum(shape[i] * t[quad[i]] for i in range(4))
            total += h * (temperature - t_sink) * jac
    return total


def balance(mesh_path, directory, t_fixed, t_in, mass_flow):
    t_fixed, t_in, m = map(float, (t_fixed, t_in, mass_flow))
    nodes, elements, nsets, _ = read_inp(mesh_path)
    top = max(p[2] for n, p in nodes.items() if n in set(nsets["NALL"]))
    extent = max(p[2] for p in nodes.values()) - min(p[2] for p in nodes.values())
    fixed_nodes = [n for n in nsets["NALL"] if nodes[n][2] > top - 1e-9 * extent]
    place(mesh_path, directory)
    with open(os.path.join(directory, "mesh.fixed.inp"), "w") as f:
        f.write("*NSET, NSET=FIXED\n" + "".join(f"{n},\n" for n in fixed_nodes))
    boundary = f"FIXED, 11, 11, {t_fixed}\nPIPE_1_WATER_IN, 11, 11, {t_in}\n"
    with open(os.path.join(directory, "mesh.inp"), "a") as f:
        f.write("*INCLUDE, INPUT=mesh.fixed.inp\n")
    r = deck(directory, "balance", boundary, m,
             "*NODE PRINT, NSET=NALL\nNT\n*NODE PRINT, NSET=WATER\nNT\n*NODE PRINT, NSET=FIXED\nRFL\n")
    t = {n: v[0] for n, v in r["temperatures NALL"].items()}
    water = {n: v[0] for n, v in r["temperatures WATER"].items()}
    t_out = water[nsets["PIPE_1_WATER_OUT"][0]]
    water_heat = m * CP * (t_out - t_in)
    wall_heat = sum(gauss_film_heat(nodes, elements[e][1], face, h, t, water[sink])
                    for e, face, sink, h in films_of(mesh_path))
    flux_block = next(v for k, v in r.items() if k.endswith("FIXED") and not k.startswith("temperatures"))
    fixed_heat = sum(v[0] for v in flux_block.values())
    return {"t_out": t_out, "water_heat": water_heat, "wall_heat": wall_heat, "fixed_heat": fixed_heat,
            "error_wall": abs(wall_heat - water_heat) / abs(water_heat),
            "error_fixed": abs(abs(fixed_heat) - water_heat) / abs(water_heat)}


def mirror(forward_path, reversed_path, directory, t_fixed, t_in, mass_flow):
    temperatures, rise, inlets = [], 0.0, []
    for i, path in enumerate((forward_path, reversed_path)):
        nodes, _, nsets, _ = read_inp(path)
        inlets.append(nodes[nsets["PIPE_1_WATER_IN"][0]][0])
        zs = [nodes[n][2] for n in nsets["NALL"]]
        lo, hi = min(zs), max(zs)
        ends = [n for n in nsets["NALL"] if nodes[n][2] in (lo, hi)]
        work = os.path.join(directory, str(i))
        os.makedirs(work, exist_ok=True)
        place(path, work)
        with open(os.path.join(work, "mesh.inp"), "a") as f:
            f.write("*NSET, NSET=FIXED\n" + "".join(f"{n},\n" for n in ends))
        boundary = f"FIXED, 11, 11, {t_fixed}\nPIPE_1_WATER_IN, 11, 11, {t_in}\n"
        r = deck(work, "mirror", boundary, mass_flow, "*NODE PRINT, NSET=WATER\nNT\n")
        water = r["temperatures WATER"]
        # The temperature nodes: the ends of the D elements (the flow nodes carry no temperature).
        flow = set(nsets["PIPE_1_WATER_FLOW"])
        temperatures.append({nodes[n]: v[0] for n, v in water.items() if n not in flow})
        rise = max(rise, abs(water[nsets["PIPE_1_WATER_OUT"][0]][0] - float(t_in)))
    forward, backward = temperatures
    xs = [p[0] for p in forward]
    mid = (min(xs) + max(xs)) / 2
    worst, matched = 0.0, 0
    for p, value in forward.items():
        q = min(backward, key=lambda b: math.dist(b, (2 * mid - p[0], p[1], p[2])))
        if math.dist(q, (2 * mid - p[0], p[1], p[2])) > 1e-6 * max(1.0, abs(mid)):
            continue
        matched += 1
        worst = max(worst, abs(backward[q] - value))
    return {"nodes": len(forward), "matched": matched, "max_difference": worst, "rise": rise,
            "error": worst / rise if rise else 0.0, "inlets": inlets}


def transient(deck_path, mesh_path, directory):
    for suffix in (".inp", ".films.inp"):
        source = mesh_path[:-4] + suffix
        shutil.copy(source, os.path.join(directory, os.path.basename(source)))
    shutil.copy(deck_path, os.path.join(directory, "deck.inp"))
    times, outlets = [], {}
    for title, values in dat_blocks(run_ccx(directory, "deck")):
        m = re.match(r"temperatures for set (PIPE_\d+)_WATER_OUT and time\s+(\S+)", title)
        if m:
            if not times or float(m[2]) > times[-1]:
                times.append(float(m[2]))
            outlets.setdefault(m[1].lower(), []).extend(v[0] for v in list(values.values())[:1])
    return {"times": times, "outlets": outlets}


def main():
    mode, args = sys.argv[1], sys.argv[2:]
    result = {"structure": structure, "fixed": fixed, "balance": balance, "mirror": mirror,
              "transient": transient}[mode](*args)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
