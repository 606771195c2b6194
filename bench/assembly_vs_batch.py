#!/usr/bin/python3
"""A dam section meshed as one assembly against its blocks meshed one by one: `tubemesh
make-dam --assembled` writes the section and the blocks' manifest from the same draw, then
`tubemesh batch` meshes the blocks and `tubemesh mesh --assembly` the section, each on the
same threads. Compared: element counts per kind (the assembly's over the batch's sum), quality
per kind (min and cell-weighted mean over the blocks against the assembly's), wall time and
peak memory.

  bench/assembly_vs_batch.py [--build-dir build/release] [--threads 2] [--work DIR]
                             [--out bench/results/assembly-DATE.json]
      [make-dam options after --, default: the 3 x 3 section of 20 x 15 x 3 lifts]

The 3 x 3 section takes about 6 minutes on 2 cores (make-dam and both meshings).
"""
import argparse
import datetime
import json
import os
import subprocess
import tempfile

from gnu_time import measured

SECTION = ["--columns", "3", "--lifts", "3", "--width", "20", "--depth", "15", "--lift-height", "3",
           "--diameter", "0.032", "--crossing-pipes", "2"]
KINDS = [("tets", "tet_collapse"), ("pyramids", "pyramid_scaled_jacobian"), ("hexes", "hex_scaled_jacobian")]


def timed_mib(command):
    """Wall seconds and peak RSS (MiB) of the command and the processes it waited for."""
    seconds, kib = measured([command])
    return seconds, kib / 1024


def load(path):
    with open(path) as f:
        return json.load(f)


def batch_totals(outdir, block_ids):
    """Counts per kind summed over the blocks; per kind the smallest min and the cell-weighted mean."""
    reports = [load(os.path.join(outdir, f"{b}.report.json")) for b in block_ids]
    out = {"nodes": sum(r["nodes"] for r in reports)}
    for kind, measure in KINDS:
        counts = [r["quality"][measure]["count"] for r in reports]
        n = sum(counts)
        out[kind] = sum(r[kind] for r in reports)
        out[measure] = {
            "min": min(r["quality"][measure]["min"] for r, c in zip(reports, counts) if c) if n else None,
            "mean": sum(r["quality"][measure]["mean"] * c for r, c in zip(reports, counts)) / n if n else None}
    out["cpu_seconds_in_blocks"] = sum(r["total_seconds"] for r in reports)
    return out


def assembly_totals(report):
    out = {"nodes": report["nodes"]}
    for kind, measure in KINDS:
        q = report["quality"][measure]
        out[kind] = report[kind]
        out[measure] = {"min": q["min"] if q["count"] else None, "mean": q["mean"] if q["count"] else None}
    return out


def compare(batch, assembly):
    rows = {}
    for kind, measure in KINDS:
        b, a = batch[measure], assembly[measure]
        rows[kind] = {
            "batch": batch[kind], "assembly": assembly[kind],
            "count_ratio": assembly[kind] / batch[kind] if batch[kind] else None,
            "min_difference": a["min"] - b["min"] if a["min"] is not None and b["min"] is not None else None,
            "mean_difference": a["mean"] - b["mean"] if a["mean"] is not None and b["mean"] is not None else None}
    return rows


def markdown(result):
    c, t = result["comparison"], result["times"]
    lines = [f"# Assembly against batch, {result['date']}", "",
             f"Section: `make-dam {' '.join(result['make_dam'])} --assembled`, {result['blocks']} blocks; "
             f"{result['threads']} threads each way. Load before the runs: {result['load']}.", "",
             "| kind | batch (sum of blocks) | assembly | ratio | min: batch / assembly | mean: batch / assembly |",
             "|---|---|---|---|---|---|"]
    for kind, measure in KINDS:
        r = c[kind]
        b, a = result["batch"][measure], result["assembly"][measure]
        fmt = lambda v: "-" if v is None else f"{v:.4f}"
        ratio = "-" if r["count_ratio"] is None else f"{r['count_ratio']:.4f}"
        lines.append(f"| {kind} | {r['batch']} | {r['assembly']} | {ratio} | {fmt(b['min'])} / {fmt(a['min'])} | "
                     f"{fmt(b['mean'])} / {fmt(a['mean'])} |")
    lines += ["", "| | batch | assembly | assembly / batch |", "|---|---|---|---|",
              f"| wall time | {t['batch_seconds']:.1f} s | {t['assembly_seconds']:.1f} s | {t['ratio']:.2f} |",
              f"| peak memory | {t['batch_peak_mib']:.0f} MiB | {t['assembly_peak_mib']:.0f} MiB | |",
              f"| nodes | {result['batch']['nodes']} | {result['assembly']['nodes']} | |", ""]
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build-dir", default="build/release")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--work", help="folder for the files (default: a temporary one, removed)")
    ap.add_argument("--out", default=f"bench/results/assembly-{datetime.date.today()}.json")
    ap.add_argument("make_dam", nargs="*", default=SECTION)
    args = ap.parse_args()
    tubemesh = os.path.abspath(os.path.join(args.build_dir, "tools", "tubemesh"))
    keep = tempfile.TemporaryDirectory() if not args.work else None
    work = args.work or keep.name
    dam = os.path.join(work, "dam")
    subprocess.run([tubemesh, "make-dam", *args.make_dam, "--assembled", "--quiet", "-o", dam], check=True)
    manifest = load(os.path.join(dam, "manifest.json"))
    ids = [b["id"] for b in manifest["blocks"]]
    load_before = open("/proc/loadavg").read().split()[:3]

    batch_out = os.path.join(work, "batch")
    batch_seconds, batch_peak = timed_mib([tubemesh, "batch", os.path.join(dam, "manifest.json"), "-o", batch_out,
                                       "--threads", str(args.threads), "--formats", "msh", "--quiet"])
    report = os.path.join(work, "assembly.json")
    assembly_seconds, assembly_peak = timed_mib([tubemesh, "mesh", "--assembly", "--threads", str(args.threads), "--quiet",
                                             os.path.join(dam, "section.step"), "-o",
                                             os.path.join(work, "assembly.msh"), "--report", report])
    batch, assembly = batch_totals(batch_out, ids), assembly_totals(load(report))
    result = {"date": str(datetime.date.today()), "make_dam": args.make_dam, "blocks": len(ids),
              "threads": args.threads, "load": " ".join(load_before),
              "batch": batch, "assembly": assembly, "comparison": compare(batch, assembly),
              "assembly_report": load(report)["assembly"],
              "assembly_phases": [{"name": p["name"], "seconds": p["seconds"]} for p in load(report)["phases"]],
              "times": {"batch_seconds": batch_seconds, "assembly_seconds": assembly_seconds,
                        "ratio": assembly_seconds / batch_seconds, "batch_peak_mib": batch_peak,
                        "assembly_peak_mib": assembly_peak}}
    with open(args.out, "w") as f:
        json.dump(result, f, indent=2)
        f.write("\n")
    with open(os.path.splitext(args.out)[0] + ".md", "w") as f:
        f.write(markdown(result))
    print(markdown(result))


if __name__ == "__main__":
    main()
