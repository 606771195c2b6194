"""What the CalculiX test scripts (calculix_run.py, calculix_steps.py, calculix_network.py) share:
reading a tubemesh .inp, running Debian's ccx on a deck in a folder and reading the *NODE PRINT
blocks of the .dat file it writes."""
import os
import subprocess
import sys


def read_inp(path):
    """Nodes (label -> (x, y, z)), elements (label -> (type, nodes)), node sets and element sets
    (upper-case name -> labels; lists and GENERATE ranges, as tubemesh writes them)."""
    nodes, elements, nsets, elsets = {}, {}, {}, {}
    keyword, params = None, {}
    with open(path) as f:
        for line in f:
            if line.startswith("**"):
                continue
            if line.startswith("*"):
                head = [p.strip() for p in line.split(",")]
                keyword = head[0].upper()
                params = {p.split("=")[0].upper(): (p.split("=")[1].upper() if "=" in p else "") for p in head[1:]}
                for key, sets in (("NSET", nsets), ("ELSET", elsets)):
                    if key in params:
                        sets.setdefault(params[key], [])
                continue
            fields = [v.strip() for v in line.split(",") if v.strip()]
            if not fields:
                continue
            if keyword == "*NODE":
                nodes[int(fields[0])] = tuple(float(v) for v in fields[1:4])
                if "NSET" in params:
                    nsets[params["NSET"]].append(int(fields[0]))
            elif keyword == "*ELEMENT":
                label = int(fields[0])
                elements[label] = (params["TYPE"], [int(v) for v in fields[1:]])
                if "ELSET" in params:
                    elsets[params["ELSET"]].append(label)
            elif keyword in ("*NSET", "*ELSET"):
                target = nsets[params["NSET"]] if keyword == "*NSET" else elsets[params["ELSET"]]
                values = [int(v) for v in fields]
                target += list(range(values[0], values[1] + 1, values[2])) if "GENERATE" in params else values
    return nodes, elements, nsets, elsets


def run_ccx(directory, job):
    """Runs ccx on DIR/JOB.inp on one thread and returns the path of the .dat it wrote; exits with
    status 1 and ccx's last lines on stderr when it fails."""
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1")
    done = subprocess.run(["ccx", "-i", job], cwd=directory, capture_output=True, text=True, env=env)
    if done.returncode != 0 or "*ERROR" in done.stdout or "*ERROR" in done.stderr:
        errors = [l for l in (done.stdout + done.stderr).splitlines() if l.strip()]
        sys.exit(f"ccx failed on {job}.inp (exit {done.returncode}):\n" + "\n".join(errors[-30:]))
    return os.path.join(directory, job + ".dat")


def dat_blocks(path):
    """The blocks of a .dat file in order: (title line, node -> printed values). A title is
    "temperatures for set NALL and time  0.1000000E+01", "displacements (vx,vy,vz) ...", ..."""
    blocks = []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if not parts[0].isdigit():
                blocks.append((line.strip(), {}))
            elif blocks:
                blocks[-1][1][int(parts[0])] = [float(v) for v in parts[1:]]
    return blocks
