#!/usr/bin/python3
"""The paper's Table 1 against tubemesh on the paper's own three examples at the paper's S:
the paper's row, ours with --economy and with default options, and Gmsh all-tet on the same
CAD solid, every mesh scored with our measures (`tubemesh check` reads Gmsh's file).

  bench/table1.py [--build-dir build/release] [--out table.md] [--json table.json]

About a minute on 2 cores (tubemesh on 1 thread; Gmsh HXT on 2). Needs Debian's /usr/bin/python3
with python3-gmsh. Gmsh meshes the STEP file that `tubemesh make-block --preset paper-exN`
writes, with S as its largest size and 8 elements per 2 pi of curvature, so the pipe is
resolved as the paper's all-tet reference resolved it; its coordinates are kept in the
file's unit (OCCTargetUnit).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import gmsh
from gmsh_scored import scored_gmsh_mesh

# preset, S, Gmsh's target unit (the STEP file's), the paper's column (Table 1 and section 6).
EXAMPLES = [
    ("paper-ex1", 0.6, "M", dict(elements=58594, tets=56446, tet_min=0.362795, tet_mean=0.819253,
                                 pyr_min=0.563902, jm_min=0.669033, cond_max=None, all_tet=1061195)),
    ("paper-ex2", 1.1, "MM", dict(elements=9412, tets=8932, tet_min=0.303524, tet_mean=0.800367,
                                  pyr_min=0.450880, jm_min=0.644548, cond_max=None, all_tet=68154)),
    ("paper-ex3", 40, "MM", dict(elements=6997, tets=6885, tet_min=0.258356, tet_mean=0.811476,
                                 pyr_min=0.369464, jm_min=0.498896, cond_max=None, all_tet=21496)),
]
CURVATURE_ELEMENTS = 8


def ours(tubemesh, step, size, options, folder):
    report = os.path.join(folder, "report.json")
    subprocess.run([tubemesh, "mesh", step, "--size", str(size), *options, "--threads", "1", "--quiet",
                    "--report", report, "-o", os.path.join(folder, "ours.msh")], check=True)
    with open(report) as f:
        r = json.load(f)
    q = r["quality"]
    return dict(elements=r["hexes"] + r["pyramids"] + r["tets"], tets=r["tets"], hexes=r["hexes"],
                pyramids=r["pyramids"], tet_min=q["tet_collapse"]["min"], tet_mean=q["tet_collapse"]["mean"],
                pyr_min=q["pyramid_scaled_jacobian"]["min"], jm_min=q["hex_scaled_jacobian"]["min"],
                cond_max=q["hex_condition"]["max"], volume=r["check"]["volume"])


def gmsh_all_tet(tubemesh, step, size, unit, folder):
    q = scored_gmsh_mesh(tubemesh, step, os.path.join(folder, "gmsh.msh"),
                         {"Mesh.MeshSizeMax": size, "Mesh.MeshSizeFromCurvature": CURVATURE_ELEMENTS,
                          "Mesh.Algorithm3D": 10, "General.NumThreads": 2},  # 10: HXT
                         {"Geometry.OCCTargetUnit": unit})
    return dict(elements=q["tet_collapse"]["count"], tets=q["tet_collapse"]["count"],
                tet_min=q["tet_collapse"]["min"], tet_mean=q["tet_collapse"]["mean"])


def cell(v, fmt="%.3f"):
    if v is None:
        return "-"
    return "{:,}".format(v) if isinstance(v, int) else fmt % v


def rows_for(name, paper, economy, default, gm, cad_volume):
    def row(label, r):
        vol = "-" if "volume" not in r else "%.1e" % abs(r["volume"] / cad_volume - 1)
        return "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            name, label, cell(r["elements"]), cell(r.get("tets")), cell(r["tet_min"]), cell(r["tet_mean"]),
            cell(r.get("pyr_min")), cell(r.get("jm_min")), cell(r.get("cond_max"), "%.2f"), vol)
    return [row("paper", paper), row("economy", economy), row("default", default),
            row("Gmsh all-tet (paper: %s tets)" % "{:,}".format(paper["all_tet"]), gm)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build-dir", default="build/release")
    parser.add_argument("--out")
    parser.add_argument("--json")
    args = parser.parse_args()
    tubemesh = os.path.abspath(os.path.join(args.build_dir, "tools", "tubemesh"))
    header = ["example", "mesh", "elements", "tets", "tet min", "tet mean", "pyramid min", "hex J_m min",
              "hex Cond max", "volume error"]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    results = {}
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        with tempfile.TemporaryDirectory() as folder:
            for name, size, unit, paper in EXAMPLES:
                step = os.path.join(folder, name + ".step")
                made = subprocess.run([tubemesh, "make-block", "--preset", name, "-o", step], check=True,
                                      capture_output=True, text=True).stdout
                cad_volume = float(made.split("volume ")[1].split(",")[0])
                economy = ours(tubemesh, step, size, ["--economy"], folder)
                default = ours(tubemesh, step, size, [], folder)
                gm = gmsh_all_tet(tubemesh, step, size, unit, folder)
                results[name] = dict(S=size, cad_volume=cad_volume, paper=paper, economy=economy, default=default,
                                     gmsh=gm)
                lines += rows_for(name, paper, economy, default, gm, cad_volume)
                print("\n".join(lines[-4:]), file=sys.stderr)
    finally:
        gmsh.finalize()
    table = "\n".join(lines) + "\n"
    if args.out:
        with open(args.out, "w") as f:
            f.write(table)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
    sys.stdout.write(table)


if __name__ == "__main__":
    main()
