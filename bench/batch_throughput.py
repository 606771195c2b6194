#!/usr/bin/python3
"""Throughput of batch meshing: a dam from `tubemesh make-dam` (48 blocks by default: 4
columns x 12 lifts of realistic lifts, about half a million elements each) meshed by
`tubemesh batch` on 1 and on 2 threads, as two shards side by side joined by --merge, and
under `mpirun -np 2 tubemesh-mpi`. Per mode: wall time, blocks per minute, elements per
second, the largest process's peak memory, and the 2-thread / 1-thread throughput ratio. Every
mode must write the same bytes: the script checks the catalogues' output hashes agree.

  bench/batch_throughput.py [--build-dir build/release] [--columns 4] [--lifts 12]
                            [--out bench/results/batch-throughput-DATE.json]

About 25 minutes on 2 cores for the 48 blocks (the 1-thread run alone about 9). Run it on an
otherwise idle machine. Needs GNU time (/usr/bin/time) and, for the MPI row, tubemesh-mpi and
mpirun (tools/setup.sh installs Open MPI); the row is skipped when either is missing.
"""
import argparse
import csv
import datetime
import io
import json
import os
import shutil
import subprocess
import tempfile

from gnu_time import measured

MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}


def catalogue(tubemesh, outdir):
    out = subprocess.run([tubemesh, "batch", "--status", outdir, "--csv"], capture_output=True, text=True).stdout
    return list(csv.DictReader(io.StringIO(out)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build-dir", default="build/release")
    ap.add_argument("--columns", type=int, default=4)
    ap.add_argument("--lifts", type=int, default=12)
    ap.add_argument("--out", default=f"bench/results/batch-throughput-{datetime.date.today()}.json")
    a = ap.parse_args()
    tubemesh = os.path.abspath(os.path.join(a.build_dir, "tools", "tubemesh"))
    mpi_driver = os.path.abspath(os.path.join(a.build_dir, "tools", "tubemesh-mpi"))
    mpirun = shutil.which("mpirun")

    work = tempfile.mkdtemp(prefix="tubemesh-batch-bench-")
    dam = os.path.join(work, "dam")
    subprocess.run([tubemesh, "make-dam", "--columns", str(a.columns), "--lifts", str(a.lifts), "-o", dam,
                    "--quiet"], check=True)
    manifest = os.path.join(dam, "manifest.json")
    out = lambda name: os.path.join(work, name)
    modes = {
        "1 thread": [[tubemesh, "batch", manifest, "-o", out("t1"), "--threads", "1", "--quiet"]],
        "2 threads": [[tubemesh, "batch", manifest, "-o", out("t2"), "--threads", "2", "--quiet"]],
        "2 shards of 1 thread": [[tubemesh, "batch", manifest, "-o", out("shards"), "--threads", "1",
                                  "--shard", f"{i}/2", "--quiet"] for i in range(2)],
    }
    if mpirun and os.path.exists(mpi_driver):
        modes["mpirun -np 2"] = [[mpirun, "--oversubscribe", "-np", "2", mpi_driver, "batch", manifest, "-o",
                                  out("mpi"), "--threads-per-block", "1", "--quiet"]]
    dirs = {"1 thread": "t1", "2 threads": "t2", "2 shards of 1 thread": "shards", "mpirun -np 2": "mpi"}

    rows, reference = [], None
    for name, commands in modes.items():
        seconds, peak_kib = measured(commands, env={**os.environ, **MPI_ENV}, ok=(0, 1))
        if name.startswith("2 shards"):
            subprocess.run([tubemesh, "batch", "--merge", out("shards"), "--quiet"], check=True)
        cat = catalogue(tubemesh, out(dirs[name]))
        hashes = {r["id"]: r["outputs"] for r in cat}
        if reference is None:
            reference = hashes
        elements = sum(int(r["hexes"]) + int(r["pyramids"]) + int(r["tets"]) for r in cat if r["status"] == "done")
        rows.append({"mode": name, "blocks": len(cat), "done": sum(r["status"] == "done" for r in cat),
                     "seconds": round(seconds, 1), "blocks_per_minute": round(len(cat) / seconds * 60, 2),
                     "elements": elements, "elements_per_second": round(elements / seconds),
                     "peak_rss_mib_largest_process": round(peak_kib / 1024), "same_bytes_as_1_thread": hashes == reference})
        print(json.dumps(rows[-1]), flush=True)

    by = {r["mode"]: r for r in rows}
    result = {"benchmark": "batch throughput", "dam": f"make-dam --columns {a.columns} --lifts {a.lifts} (seed 1)",
              "machine": f"{os.cpu_count()} cores", "date": str(datetime.date.today()), "modes": rows,
              # Other work on the machine skews every figure: the 1-minute load when the run ended.
              "load_average_at_end": round(os.getloadavg()[0], 2),
              "ratio_2_threads_over_1": round(by["2 threads"]["elements_per_second"] /
                                              by["1 thread"]["elements_per_second"], 3)}
    with open(a.out, "w") as f:
        json.dump(result, f, indent=2)
        f.write("\n")
    print(f"ratio 2 threads / 1 thread: {result['ratio_2_threads_over_1']}; wrote {a.out}")
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
