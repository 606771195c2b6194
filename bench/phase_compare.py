#!/usr/bin/python3
"""Per-phase time, throughput, thread speed-up and memory of two tubemesh builds in one run:
an older build (BASE) beside the current one (NEW), on the serpentine lift (default options)
and the built-in dam block at --size 0.3, each at 1 and 2 threads, the runs interleaved so
that both builds see the same machine. Per case, build and thread count: the median over the
repetitions of every phase's seconds from `--report`, elements per second of the element-making
phases (sweep: hexes, pyramids, tets), the 1 -> 2 thread speed-up per phase and for the run
after import, and bytes per element of resident growth (peak RSS of the run minus that of
`tubemesh --version`, which loads the same libraries, over all elements). Also checks that the
two thread counts of one build wrote the same bytes.

  bench/phase_compare.py BASE_TUBEMESH NEW_TUBEMESH [--repeat 3]
                         [--out bench/results/phase-compare-DATE.json]

Writes the JSON and a Markdown table beside it (same name, .md). About 2 minutes per repetition
on 2 cores. Run it on an otherwise idle machine; needs GNU time (/usr/bin/time).
"""
import argparse
import datetime
import filecmp
import json
import os
import statistics
import subprocess
import tempfile

from gnu_time import measured

# Phases that make elements, and the report field that counts them.
MADE = {"sweep": "hexes", "pyramids": "pyramids", "tets": "tets"}
# The run after import: what the thread count can speed up (import and tube search are serial).
NOT_AFTER_IMPORT = {"import", "build"}


def run_case(tubemesh, args, threads, work, tag):
    """One meshing run: (report dict, peak KiB, mesh path)."""
    report = os.path.join(work, f"{tag}.json")
    mesh = os.path.join(work, f"{tag}.msh")
    kib = measured([[tubemesh, "mesh", "--quiet", "--threads", str(threads), "-o", mesh, "--report", report] + args])[1]
    with open(report) as f:
        return json.load(f), kib, mesh


def summarise(runs, base_kib):
    """Median phase seconds and the figures derived from them, over repeated runs of one setting."""
    first = runs[0][0]
    phases = [p["name"] for p in first["phases"]]
    seconds = {name: statistics.median(next(p["seconds"] for p in r["phases"] if p["name"] == name)
                                       for r, _, _ in runs) for name in phases}
    elements = first["hexes"] + first["pyramids"] + first["tets"]
    kib = statistics.median(k for _, k, _ in runs)
    out = {
        "phases": seconds,
        "total_seconds": statistics.median(r["total_seconds"] for r, _, _ in runs),
        "after_import_seconds": sum(s for n, s in seconds.items() if n not in NOT_AFTER_IMPORT),
        "elements": elements,
        "made": {n: first[f] for n, f in MADE.items()},
        "per_second": {n: first[f] / seconds[n] for n, f in MADE.items() if seconds.get(n)},
        "peak_mib": kib / 1024,
        "bytes_per_element": (kib - base_kib) * 1024 / elements,
        "tet_collapse_min": first["quality"]["tet_collapse"]["min"],
        "tet_collapse_mean": first["quality"]["tet_collapse"]["mean"],
    }
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("base")
    ap.add_argument("new")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--out", default=f"bench/results/phase-compare-{datetime.date.today()}.json")
    a = ap.parse_args()
    work = tempfile.mkdtemp(prefix="phase-compare-")
    lift = os.path.join(work, "lift.step")
    subprocess.run([a.new, "make-block", "--preset", "serpentine-lift", "-o", lift], check=True,
                   stdout=subprocess.DEVNULL)
    cases = {"serpentine lift": [lift], "dam block, S 0.3": ["--size", "0.3"]}
    builds = {"base": a.base, "new": a.new}
    base_kib = {b: measured([[t, "--version"]])[1] for b, t in builds.items()}
    runs = {(c, b, th): [] for c in cases for b in builds for th in (1, 2)}
    same_bytes = {}
    for rep in range(a.repeat):
        for k, (c, args) in enumerate(cases.items()):
            for th in (1, 2):
                for b, t in builds.items():
                    tag = f"{b}-case{k}-{th}-run{rep}"
                    runs[(c, b, th)].append(run_case(t, args, th, work, tag))
    result = {"date": str(datetime.date.today()), "base": a.base, "new": a.new, "repeat": a.repeat, "cases": {}}
    for c in cases:
        result["cases"][c] = {}
        for b in builds:
            one, two = summarise(runs[(c, b, 1)], base_kib[b]), summarise(runs[(c, b, 2)], base_kib[b])
            same_bytes[(c, b)] = filecmp.cmp(runs[(c, b, 1)][0][2], runs[(c, b, 2)][0][2], shallow=False)
            speed_up = {n: one["phases"][n] / two["phases"][n] for n in one["phases"] if two["phases"].get(n)}
            speed_up["after import"] = one["after_import_seconds"] / two["after_import_seconds"]
            speed_up["whole run"] = one["total_seconds"] / two["total_seconds"]
            result["cases"][c][b] = {"1 thread": one, "2 threads": two, "speed_up": speed_up,
                                     "same_bytes_1_and_2_threads": same_bytes[(c, b)]}
    with open(a.out, "w") as f:
        json.dump(result, f, indent=1)

    lines = [f"# Phases, {result['date']}: {a.base} (base) against {a.new} (new)", "",
             f"Median of {a.repeat} runs per row, runs interleaved. s = seconds on 2 threads; /s = elements "
             "per second on 2 threads; x = 1 -> 2 thread speed-up; B/el = resident growth per element "
             "(2 threads).", ""]
    for c in cases:
        lines += [f"## {c}", "", "| phase | base s | new s | new / base | base /s | new /s | base x | new x |",
                  "|---|---|---|---|---|---|---|---|"]
        base, new = result["cases"][c]["base"], result["cases"][c]["new"]
        for n, s_new in new["2 threads"]["phases"].items():
            s_base = base["2 threads"]["phases"].get(n, float("nan"))
            rate = lambda r: f"{r['2 threads']['per_second'][n]:,.0f}" if n in r["2 threads"]["per_second"] else ""
            lines.append(f"| {n} | {s_base:.3f} | {s_new:.3f} | {s_new / s_base:.2f} | {rate(base)} | {rate(new)} | "
                         f"{base['speed_up'].get(n, float('nan')):.2f} | {new['speed_up'].get(n, float('nan')):.2f} |")
        for key, label in (("total_seconds", "whole run"), ("after_import_seconds", "after import")):
            b2, n2 = base["2 threads"][key], new["2 threads"][key]
            lines.append(f"| **{label}** | {b2:.3f} | {n2:.3f} | {n2 / b2:.2f} | | | "
                         f"{base['speed_up'][label]:.2f} | {new['speed_up'][label]:.2f} |")
        lines += ["", f"Elements: base {base['2 threads']['elements']:,}, new {new['2 threads']['elements']:,}; "
                      f"B/el base {base['2 threads']['bytes_per_element']:.0f}, new {new['2 threads']['bytes_per_element']:.0f}; "
                      f"tet collapse min / mean base {base['2 threads']['tet_collapse_min']:.4f} / "
                      f"{base['2 threads']['tet_collapse_mean']:.4f}, new {new['2 threads']['tet_collapse_min']:.4f} / "
                      f"{new['2 threads']['tet_collapse_mean']:.4f}; same bytes at 1 and 2 threads: base "
                      f"{base['same_bytes_1_and_2_threads']}, new {new['same_bytes_1_and_2_threads']}", ""]
    with open(os.path.splitext(a.out)[0] + ".md", "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
