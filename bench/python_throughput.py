#!/usr/bin/python3
"""Element throughput of the Python module on the five reference cases, and its overhead
against the CLI on the same STEP files and options.

Each case is built once as STEP (tubemesh.make_block). Then, alternately, `repeats` times:
  Python: tubemesh.mesh(step, size=S, threads=T) and write(.msh), in this process;
  CLI:    tubemesh mesh step --size S --threads T -o out.msh --quiet --report r.json, a process.
Both import, recognise the tubes, mesh, check and write the same mesh. Per case the fastest
run of each is kept (the machine is shared: the minimum is the least disturbed run).
Printed per case: elements, Python and CLI wall seconds, elements per second in Python, the
wall overhead (Python / CLI - 1; the CLI's includes starting a process) and the engine-time
overhead (the reports' total_seconds: the same phases timed inside each host).

usage: PYTHONPATH=build/release/python bench/python_throughput.py [--cli build/release/tools/tubemesh]
       [--repeats 5] [--threads 0] [--cases paper-ex1,...] [--json OUT.json]
"""
import argparse
import json
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

import tubemesh

# The reference cases (bench/reference_cases.cpp): name, preset, S (None: the default).
CASES = [
    ("paper-ex1", "paper-ex1", 0.6),
    ("paper-ex2", "paper-ex2", 1.1),
    ("paper-ex3", "paper-ex3", 40.0),
    ("serpentine-lift", "serpentine-lift", None),
    ("dam-block", "paper-ex1", None),
]


def python_run(step, out, size, threads):
    t0 = time.perf_counter()
    r = tubemesh.mesh(step, size=size, threads=threads)
    r.write(out)
    wall = time.perf_counter() - t0
    cells = len(r.tets) + len(r.pyramids) + len(r.hexes)
    return wall, r.report["total_seconds"], cells


def cli_run(cli, step, out, report, size, threads):
    args = [cli, "mesh", str(step), "-o", str(out), "--quiet", "--report", str(report)]
    if size is not None:
        args += ["--size", repr(size)]
    if threads:
        args += ["--threads", str(threads)]
    t0 = time.perf_counter()
    subprocess.run(args, check=True)
    wall = time.perf_counter() - t0
    r = json.loads(pathlib.Path(report).read_text())
    return wall, r["total_seconds"], r["tets"] + r["pyramids"] + r["hexes"]


def main():
    root = pathlib.Path(__file__).resolve().parent.parent
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=str(root / "build/release/tools/tubemesh"))
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--threads", type=int, default=0, help="0: all cores")
    parser.add_argument("--cases", default=",".join(c[0] for c in CASES))
    parser.add_argument("--json", help="also write the rows as JSON")
    args = parser.parse_args()
    wanted = args.cases.split(",")
    threads = args.threads or None
    rows = []
    print(f"{'case':<16} {'elements':>9} {'python s':>9} {'cli s':>9} {'python el/s':>12} "
          f"{'wall overhead':>13} {'engine overhead':>15}")
    with tempfile.TemporaryDirectory(prefix="tubemesh-bench-") as tmp:
        tmp = pathlib.Path(tmp)
        for name, preset, size in CASES:
            if name not in wanted:
                continue
            step = tmp / f"{preset}.step"
            if not step.exists():
                tubemesh.make_block(step, preset=preset)
            py, cli = [], []
            for _ in range(args.repeats):
                py.append(python_run(step, tmp / "py.msh", size, threads))
                cli.append(cli_run(args.cli, step, tmp / "cli.msh", tmp / "cli.json", size, threads))
            if {c for _, _, c in py} != {c for _, _, c in cli}:
                sys.exit(f"{name}: Python and the CLI made different meshes")
            py_wall, cli_wall = min(w for w, _, _ in py), min(w for w, _, _ in cli)
            py_engine, cli_engine = min(e for _, e, _ in py), min(e for _, e, _ in cli)
            cells = py[0][2]
            row = {"case": name, "elements": cells, "repeats": args.repeats, "threads": args.threads,
                   "python_wall_s": py_wall, "cli_wall_s": cli_wall,
                   "python_wall_median_s": statistics.median(w for w, _, _ in py),
                   "cli_wall_median_s": statistics.median(w for w, _, _ in cli),
                   "python_engine_s": py_engine, "cli_engine_s": cli_engine,
                   "python_elements_per_s": cells / py_wall,
                   "wall_overhead": py_wall / cli_wall - 1, "engine_overhead": py_engine / cli_engine - 1}
            rows.append(row)
            print(f"{name:<16} {cells:>9} {py_wall:>9.3f} {cli_wall:>9.3f} {cells / py_wall:>12.0f} "
                  f"{100 * row['wall_overhead']:>12.1f}% {100 * row['engine_overhead']:>14.1f}%", flush=True)
    total_py = sum(r["python_wall_s"] for r in rows)
    total_cli = sum(r["cli_wall_s"] for r in rows)
    print(f"{'all':<16} {sum(r['elements'] for r in rows):>9} {total_py:>9.3f} {total_cli:>9.3f} "
          f"{sum(r['elements'] for r in rows) / total_py:>12.0f} {100 * (total_py / total_cli - 1):>12.1f}%")
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps({"machine_load": os.getloadavg(), "rows": rows}, indent=2) + "\n")


if __name__ == "__main__":
    main()
