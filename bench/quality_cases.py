#!/usr/bin/env python3
"""Tet quality of two builds (or two option sets) on the reference cases and random blocks.

    bench/quality_cases.py run TUBEMESH OUTDIR [--steps DIR] [--threads 2] [--seeds 50] [-- MESH FLAGS...]
    bench/quality_cases.py compare BASEDIR NEWDIR

`run` meshes paper-ex1 (S 0.6), paper-ex2 (S 1.1), paper-ex3 (S 40), the serpentine lift, the built-in dam
block and random blocks 1..N, one `--report` JSON per case in OUTDIR (a case whose report exists is skipped).
The STEP inputs are written once into --steps (default OUTDIR/../steps) by the first binary that needs them,
so that two builds mesh the same files. `compare` prints per case the tet collapse minimum and mean and the
element count, flags a lower minimum or a mean more than 0.005 lower, and sums up the mean changes.
"""
import argparse
import json
import os
import subprocess
import sys

CASES = [("paper-ex1", ["--size", "0.6"]), ("paper-ex2", ["--size", "1.1"]), ("paper-ex3", ["--size", "40"]),
         ("serpentine-lift", [])]


def cases(seeds):
    yield from CASES
    yield "dam-block", None  # the built-in block: no input file
    for n in range(1, seeds + 1):
        yield f"seed{n}", []


def step_of(tubemesh, steps, name):
    path = os.path.join(steps, name + ".step")
    if not os.path.exists(path):
        which = ["--seed", name[4:]] if name.startswith("seed") else ["--preset", name]
        subprocess.run([tubemesh, "make-block", *which, "-o", path], check=True, capture_output=True)
    return path


def run(a):
    steps = a.steps or os.path.join(os.path.dirname(os.path.abspath(a.outdir)), "steps")
    os.makedirs(a.outdir, exist_ok=True)
    os.makedirs(steps, exist_ok=True)
    scratch = os.path.join(a.outdir, "scratch.msh")
    for name, extra in cases(a.seeds):
        report = os.path.join(a.outdir, name + ".json")
        if os.path.exists(report):
            continue
        source = [] if extra is None else [step_of(a.tubemesh, steps, name), *extra]
        r = subprocess.run([a.tubemesh, "mesh", "--quiet", "--threads", str(a.threads), "-o", scratch, "--report",
                            report, *source, *a.flags], capture_output=True, text=True)
        if r.returncode:
            print(f"{name}: failed: {r.stderr.strip()}")
    if os.path.exists(scratch):
        os.remove(scratch)


def summary(path):
    r = json.load(open(path))
    q = r["quality"]["tet_collapse"]
    return q["min"], q["mean"], r["tets"] + r["hexes"] + r["pyramids"]


def compare(a):
    changes, lower = [], []
    for f in sorted(os.listdir(a.base)):
        new = os.path.join(a.new, f)
        if not f.endswith(".json") or not os.path.exists(new):
            continue
        (m0, q0, e0), (m1, q1, e1) = summary(os.path.join(a.base, f)), summary(new)
        changes.append(q1 - q0)
        flags = (" MIN-LOWER" if m1 < m0 - 1e-12 else "") + (" MEAN-LOWER" if q1 < q0 - 0.005 else "")
        if m1 < m0 - 1e-12:
            lower.append(f[:-5])
        print(f"{f[:-5]:16s} min {m0:.4f} -> {m1:.4f}  mean {q0:.4f} -> {q1:.4f}  elements {e0} -> {e1} "
              f"({(e1 / e0 - 1) * 100:+.2f} %){flags}")
    if not changes:
        sys.exit("no case in both folders")
    print(f"{len(changes)} cases: mean change {min(changes):+.4f} to {max(changes):+.4f}, average "
          f"{sum(changes) / len(changes):+.4f}; minimum lower in {len(lower)}{': ' + ', '.join(lower) if lower else ''}")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="command", required=True)
    r = sub.add_parser("run")
    r.add_argument("tubemesh")
    r.add_argument("outdir")
    r.add_argument("--steps")
    r.add_argument("--threads", type=int, default=2)
    r.add_argument("--seeds", type=int, default=50)
    c = sub.add_parser("compare")
    c.add_argument("base")
    c.add_argument("new")
    argv = sys.argv[1:]
    cut = argv.index("--") if "--" in argv else len(argv)
    a = p.parse_args(argv[:cut])
    a.flags = argv[cut + 1:]  # after --: more `tubemesh mesh` flags
    run(a) if a.command == "run" else compare(a)


if __name__ == "__main__":
    main()
