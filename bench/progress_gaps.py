#!/usr/bin/env python3
"""How often a run tells its caller it is alive, and how fast Ctrl-C stops it.

  gaps:      one run of tubemesh.mesh with a progress callback that timestamps every event;
             per phase, the longest time between two events a listener saw while that phase
             ran (the gap into a phase's first event counts for that phase).
  interrupt: runs of the same mesh in a child process sent SIGINT at given moments; the latency
             is the time from the parent's kill() to the child catching KeyboardInterrupt
             (both read CLOCK_MONOTONIC, which one machine shares between processes).
  cli:       the CLI sent SIGINT at given moments: the time until it exited, its exit status,
             and whether an output file or a temporary one was left.

  PYTHONPATH=build/release/python /usr/bin/python3 bench/progress_gaps.py gaps --source lift.step --size 0.2
  ... interrupt --source lift.step --size 0.2 --at 1 3 6 10 20
  ... cli --tubemesh build/release/tools/tubemesh --source lift.step --size 0.2 --at 1 3 6 10 20
Prints one JSON document on stdout.
"""
import argparse
import json
import os
import pathlib
import signal
import subprocess
import sys
import tempfile
import time

CHILD = r"""
import sys, time, json, tubemesh
events = []
def progress(phase, done, total):
    events.append(phase)
args = json.loads(sys.argv[1])
print("ready", flush=True)
try:
    tubemesh.mesh(args["source"], size=args["size"], threads=args["threads"], progress=progress)
    print(json.dumps({"finished": True}), flush=True)
except KeyboardInterrupt:
    print(json.dumps({"finished": False, "caught_at": time.monotonic(),
                      "phase": events[-1] if events else None}), flush=True)
"""


def gaps(args):
    import tubemesh
    stamps = []  # (time, phase, done, total)

    def progress(phase, done, total):
        stamps.append((time.monotonic(), phase, done, total))

    t0 = time.monotonic()
    tubemesh.mesh(args.source, size=args.size, threads=args.threads, progress=progress)
    end = time.monotonic()
    phases = {}
    previous = t0
    longest = []  # (gap, phase, done, total, at)
    for t, phase, done, total in stamps:
        longest.append((t - previous, phase, done, total, t - t0))
        p = phases.setdefault(phase, {"events": 0, "longest_gap_s": 0.0, "first_s": t - t0})
        p["events"] += 1
        p["longest_gap_s"] = max(p["longest_gap_s"], t - previous)
        p["last_s"] = t - t0
        previous = t
    return {"mode": "gaps", "source": args.source, "size": args.size, "threads": args.threads,
            "seconds": round(end - t0, 3), "after_last_event_s": round(end - previous, 3),
            "longest_gaps": [{"gap_s": round(g, 3), "until": f"{ph} {d}/{n}", "at_s": round(a, 3)}
                             for g, ph, d, n, a in sorted(longest, reverse=True)[:args.top]],
            "phases": {k: {kk: round(vv, 3) if isinstance(vv, float) else vv for kk, vv in v.items()}
                       for k, v in phases.items()}}


def interrupt(args):
    runs = []
    for at in args.at:
        child = subprocess.Popen(
            [sys.executable, "-c", CHILD, json.dumps({"source": args.source, "size": args.size,
                                                       "threads": args.threads})],
            stdout=subprocess.PIPE, text=True, env=os.environ)
        child.stdout.readline()  # "ready": the module is imported
        time.sleep(at)
        sent = time.monotonic()
        if child.poll() is None:
            child.send_signal(signal.SIGINT)
        out, _ = child.communicate()
        line = out.strip().splitlines()[-1] if out.strip() else "{}"
        result = json.loads(line)
        result["at_s"] = at
        caught = result.pop("caught_at", None)
        result["latency_s"] = None if caught is None else round(caught - sent, 4)
        runs.append(result)
    return {"mode": "interrupt", "source": args.source, "size": args.size, "threads": args.threads, "runs": runs}


def cli(args):
    runs = []
    for at in args.at:
        with tempfile.TemporaryDirectory() as d:
            out = pathlib.Path(d) / "out.msh"
            child = subprocess.Popen([args.tubemesh, "mesh", args.source, "--size", str(args.size), "--threads",
                                      str(args.threads), "-o", str(out), "--quiet"],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            time.sleep(at)
            sent = time.monotonic()
            if child.poll() is None:
                child.send_signal(signal.SIGINT)
            _, err = child.communicate()
            runs.append({"at_s": at, "exit_s": round(time.monotonic() - sent, 4), "status": child.returncode,
                         "files_left": sorted(p.name for p in pathlib.Path(d).iterdir())})
    return {"mode": "cli", "source": args.source, "size": args.size, "threads": args.threads, "runs": runs}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=["gaps", "interrupt", "cli"])
    parser.add_argument("--source", default="paper-ex1", help="a CAD file or a preset name")
    parser.add_argument("--size", type=float, default=None)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--at", type=float, nargs="*", default=[1, 3, 6, 10], help="seconds after start")
    parser.add_argument("--top", type=int, default=12, help="gaps: how many of the longest to list")
    parser.add_argument("--tubemesh", default="build/release/tools/tubemesh")
    args = parser.parse_args()
    result = {"gaps": gaps, "interrupt": interrupt, "cli": cli}[args.mode](args)
    json.dump(result, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
