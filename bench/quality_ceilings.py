#!/usr/bin/python3
"""How high the tet-collapse mean can go on the paper's examples and the serpentine
lift: each example next to the same solid without its holes, meshed by tubemesh and by Gmsh,
all scored with our collapse measure (`tubemesh check`). A hole-free solid's mean is a
ceiling for the example: the rings, pyramids and the grading towards them only add worse tets.
The lift has no hole-free row (its volume is all grading between pipes 1.5 m apart); its rows
show what finer rings and a gentler grading buy.

  bench/quality_ceilings.py [--build-dir build/release] [--out table.md]

Runs in about a minute and a half on 2 cores (tubemesh on 1 thread, rows one after another). Needs
Debian's /usr/bin/python3 with python3-gmsh (tools/setup.sh installs it). Gmsh meshes the
hole-free solids with its Delaunay and its default optimiser (this Gmsh has no Netgen
optimiser), at the size that gives about as many tets as ours.

For each of our meshes with pyramids the table also bounds what the rest of the mesh would
have to reach for a 0.80 mean. Tets whose four corners are pyramid corners with at least two
apexes (the valleys between pyramids and the voids over ring nodes) have only fixed corners:
no move of interior points changes them (only points inserted into the voids would, as a finer
grading does). A tet of three apexes and one free point is at best what its apex triangle
allows that point alone (searched per triangle, to about 0.001). With those two groups at
that, the last column says what every other tet would have to average.

The hole-free solids are written by Gmsh's OpenCASCADE kernel, whose STEP files say
millimetre: the boxes are built 1000 times larger and meshed at 1000 S, which leaves every
shape measure unchanged.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import gmsh
from gmsh_scored import scored_gmsh_mesh
import meshio
import numpy as np

# (row label, solid, tubemesh mesh options). Solids: presets by name, or "box:X,Y,Z" /
# "cylinder:D,L" (hole-free, millimetre). Sizes: the CLI acceptance's (0.6, 1.1, 40), and what moves them.
ROWS = [
    ("paper-ex1, S 0.6 (defaults)", "paper-ex1", ["--size", "0.6"]),
    ("paper-ex1, S 0.6, paper's ring: n 4, St 0.2, axial 2.5", "paper-ex1",
     ["--size", "0.6", "--circ", "4", "--sweep-size", "0.2", "--axial-aspect", "2.5"]),
    ("paper-ex1, S 0.6, gradation 1.2 (elements spent on grading)", "paper-ex1", ["--size", "0.6", "--gradation", "1.2"]),
    ("15 x 25 x 4 box without the pipe, S 0.6", "box:15000,25000,4000", ["--size", "600"]),
    ("paper-ex2, S 1.1 (defaults)", "paper-ex2", ["--size", "1.1"]),
    ("paper-ex2, S 1.1, gradation 1.2", "paper-ex2", ["--size", "1.1", "--gradation", "1.2"]),
    ("11 x 12 x 11 box without the holes, S 1.1", "box:11000,12000,11000", ["--size", "1100"]),
    ("paper-ex2, S 1.1, the economy preset (a ring like the paper's)", "paper-ex2", ["--size", "1.1", "--economy"]),
    ("paper-ex3, S 40 (defaults)", "paper-ex3", ["--size", "40"]),
    ("paper-ex3, S 40, gradation 1.3", "paper-ex3", ["--size", "40", "--gradation", "1.3"]),
    ("paper-ex3, S 40, gradation 1.2", "paper-ex3", ["--size", "40", "--gradation", "1.2"]),
    ("paper-ex3, S 40, gradation 1.1", "paper-ex3", ["--size", "40", "--gradation", "1.1"]),
    ("paper-ex3, S 20", "paper-ex3", ["--size", "20"]),
    ("journal cylinder 295 x 300 without the oil hole, S 40", "cylinder:295,300", ["--size", "40"]),
    ("journal cylinder 295 x 300 without the oil hole, S 20", "cylinder:295,300", ["--size", "20"]),
    ("serpentine-lift (defaults)", "serpentine-lift", []),
    ("serpentine-lift, n 12 around the pipe", "serpentine-lift", ["--circ", "12"]),
    ("serpentine-lift, gradation 1.3", "serpentine-lift", ["--gradation", "1.3"]),
]
# Gmsh on the hole-free solids: (row label, solid, Gmsh size).
GMSH_ROWS = [
    ("Gmsh: 15 x 25 x 4 box", "box:15000,25000,4000", 500.0),
    ("Gmsh: 11 x 12 x 11 box", "box:11000,12000,11000", 900.0),
    ("Gmsh: journal cylinder", "cylinder:295,300", 25.0),
]


def write_quietly(path):
    """gmsh.write, without the banner OpenCASCADE's STEP writer prints on file descriptor 1."""
    sys.stdout.flush()
    saved = os.dup(1)
    with open(os.devnull, "w") as null:
        os.dup2(null.fileno(), 1)
        try:
            gmsh.write(path)
        finally:
            os.dup2(saved, 1)
            os.close(saved)


def solid_step(tubemesh, solid, folder):
    path = os.path.join(folder, solid.replace(":", "_").replace(",", "_") + ".step")
    if os.path.exists(path):
        return path
    if solid.startswith(("box:", "cylinder:")):
        kind, dims = solid.split(":")
        d = [float(v) for v in dims.split(",")]
        gmsh.clear()
        if kind == "box":
            gmsh.model.occ.addBox(0, 0, 0, *d)
        else:
            gmsh.model.occ.addCylinder(0, 0, 0, 0, 0, d[1], d[0] / 2)
        gmsh.model.occ.synchronize()
        write_quietly(path)
    else:
        subprocess.run([tubemesh, "make-block", "--preset", solid, "-o", path], check=True,
                       stdout=subprocess.DEVNULL)
    return path


def summary(quality):
    def part(key, fmt):
        q = quality[key]
        return fmt % (q["min"], q["mean"]) if q["count"] else ""
    t = quality["tet_collapse"]
    counts = sum(quality[k]["count"] for k in ("tet_collapse", "pyramid_scaled_jacobian",
                                               "hex_scaled_jacobian"))
    return [str(counts), str(t["count"]), "%.3f" % t["min"], "%.3f" % t["mean"],
            part("pyramid_scaled_jacobian", "%.3f / %.3f"), part("hex_scaled_jacobian", "%.3f / %.3f")]


def collapse(p):
    """Tet collapse of an (n, 4, 3) array of corners, unsigned; engine/quality/quality.hpp's."""
    e1, e2, e3 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]
    three_volume = 0.5 * np.abs(np.einsum("ij,ij->i", e1, np.cross(e2, e3)))
    faces = [np.cross(p[:, 2] - p[:, 1], p[:, 3] - p[:, 1]), np.cross(e2, e3), np.cross(e1, e3), np.cross(e1, e2)]
    area = 0.5 * np.sqrt(np.max([np.einsum("ij,ij->i", f, f) for f in faces], axis=0))
    return three_volume / (area * np.sqrt(area)) / (np.sqrt(2 / 3) / np.sqrt(np.sqrt(3) / 4))


def best_over_triangles(a, b, c, side):
    """Per triangle abc, the largest collapse of a tet with a fourth point on `side`'s side:
    a grid over heights and offsets from the centroid in units of the mean edge, then a
    pattern search with halving steps."""
    n = np.cross(b - a, c - a)
    n /= np.linalg.norm(n, axis=1)[:, None]
    n *= np.sign(np.einsum("ij,ij->i", side - a, n))[:, None]
    u = (b - a) / np.linalg.norm(b - a, axis=1)[:, None]
    v = np.cross(n, u)
    edge = ((np.linalg.norm(b - a, axis=1) + np.linalg.norm(c - b, axis=1) + np.linalg.norm(a - c, axis=1)) / 3)[:, None]
    base = np.stack([a, b, c], axis=1)
    best = np.zeros(len(a))
    at = (a + b + c) / 3

    def offer(x):
        nonlocal best, at
        q = collapse(np.concatenate([base, x[:, None]], axis=1))
        better = q > best
        best = np.where(better, q, best)
        at = np.where(better[:, None], x, at)

    centroid = at.copy()
    for h in np.linspace(0.3, 1.4, 12):
        for du in np.linspace(-0.4, 0.4, 7):
            for dv in np.linspace(-0.4, 0.4, 7):
                offer(centroid + (h * n + du * u + dv * v) * edge)
    for step in 0.05 / 2.0 ** np.arange(6):
        for _ in range(2):
            for d in (n, -n, u, -u, v, -v):
                offer(at + step * d * edge)
    return best


def apex_grid_bound(vtu):
    """Cells for the table's last three columns (see the module's docstring)."""
    mesh = meshio.read(vtu)
    pyramids = [c.data for c in mesh.cells if c.type == "pyramid"]
    if not pyramids:
        return ["", "", ""]
    tets = np.concatenate([c.data for c in mesh.cells if c.type == "tetra"])
    pyramids = np.concatenate(pyramids)
    kind = np.zeros(len(mesh.points), dtype=int)  # 0 other, 1 apex, 2 pyramid base
    kind[pyramids[:, :4].ravel()] = 2
    kind[pyramids[:, 4]] = 1
    q = collapse(mesh.points[tets])
    k = kind[tets]
    apexes, others = (k == 1).sum(1), (k == 0).sum(1)
    fixed = (others == 0) & (apexes >= 2)
    three = (apexes == 3) & (others == 1)
    t, kt = tets[three], k[three]
    corners = mesh.points[t[kt == 1].reshape(-1, 3)]
    free = mesh.points[t[kt == 0]]
    best = best_over_triangles(corners[:, 0], corners[:, 1], corners[:, 2], free)
    rest = ~(fixed | three)
    need = (0.80 * len(q) - q[fixed].sum() - best.sum()) / rest.sum()
    def share(group, text):
        return "%.1f %% at %s" % (100 * group.mean(), text() if group.any() else "-")
    return [share(fixed, lambda: "%.3f" % q[fixed].mean()),
            share(three, lambda: "%.3f (at best %.3f)" % (q[three].mean(), best.mean())),
            "%.1f %%: %.3f -> %.3f" % (100 * rest.mean(), q[rest].mean(), need)]


def ours(tubemesh, step, options, folder):
    report = os.path.join(folder, "report.json")
    subprocess.run([tubemesh, "mesh", step, *options, "--threads", "1", "--quiet", "--report", report,
                    "-o", os.path.join(folder, "ours.vtu")], check=True)
    with open(report) as f:
        return summary(json.load(f)["quality"]) + apex_grid_bound(os.path.join(folder, "ours.vtu"))


def gmsh_tets(tubemesh, step, size, folder):
    quality = scored_gmsh_mesh(tubemesh, step, os.path.join(folder, "gmsh.msh"),
                               {"Mesh.MeshSizeMin": size, "Mesh.MeshSizeMax": size,
                                "Mesh.Algorithm3D": 1, "Mesh.Optimize": 1})  # 1: Delaunay
    return summary(quality) + ["", "", ""]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build-dir", default="build/release")
    parser.add_argument("--out")
    args = parser.parse_args()
    tubemesh = os.path.abspath(os.path.join(args.build_dir, "tools", "tubemesh"))
    header = ["case", "elements", "tets", "tet min", "tet mean", "pyramid min / mean", "hex J_m min / mean",
              "fixed-corner apex tets", "3 apexes + 1 free", "other tets: mean now -> needed for 0.80"]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        with tempfile.TemporaryDirectory() as folder:
            for label, solid, options in ROWS:
                cells = ours(tubemesh, solid_step(tubemesh, solid, folder), options, folder)
                lines.append("| " + " | ".join([label] + cells) + " |")
                print(lines[-1], file=sys.stderr)
            for label, solid, size in GMSH_ROWS:
                cells = gmsh_tets(tubemesh, solid_step(tubemesh, solid, folder), size, folder)
                lines.append("| " + " | ".join(["%s, size %g" % (label, size)] + cells) + " |")
                print(lines[-1], file=sys.stderr)
    finally:
        gmsh.finalize()
    table = "\n".join(lines) + "\n"
    if args.out:
        with open(args.out, "w") as f:
            f.write(table)
    sys.stdout.write(table)


if __name__ == "__main__":
    main()
