#!/usr/bin/env python3
"""Fails on an include from a lower folder into a higher one (docs/architecture.md, "Layers").

Every source folder has a rank in LAYERS; a file may include project headers of its own folder
and of folders ranked below it. A folder's own files rank above its subfolders (the subfolders
are its parts). --plant FILE:HEADER adds an include that is not in the tree, so a test can show
the check fails on an upward include.
"""
import argparse
import pathlib
import re
import sys

# Lowest first. A path's folder is the longest entry that is a prefix of it.
LAYERS = [
    "engine/core",
    "engine/predicates",
    "engine/mesh",
    "engine/quality",
    "engine/geometry",
    "engine/sizing/field",
    "engine/check",
    "engine/io",
    "engine/delaunay",
    "engine/sweep",
    "engine/surface",
    "engine/pyramids",
    "engine/tets/domain",
    "engine/sizing",
    "engine/tets/recovery",
    "engine/tets/optimise",
    "engine/tets/refinement",
    "engine/tets",
    "engine/pipeline",
    "geom/model",
    "geom/import",
    "geom/builders",
    "geom/tubes",
    "geom/sizing",
    "geom",
    "geom/assembly",
    "job",
    "batch",
    "tools/cli",
    "tools/mpi",
    "python",
]
CHECKED_TOPS = ("engine", "geom", "job", "batch", "tools", "python")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def folder_of(path):
    parent = str(pathlib.PurePosixPath(path).parent)
    best = None
    for layer in LAYERS:
        if parent == layer or parent.startswith(layer + "/"):
            if best is None or len(layer) > len(best):
                best = layer
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root", help="the source tree")
    parser.add_argument("--plant", action="append", default=[], metavar="FILE:HEADER",
                        help="check as if FILE also included HEADER")
    args = parser.parse_args()
    root = pathlib.Path(args.root)
    rank = {layer: i for i, layer in enumerate(LAYERS)}

    includes = []  # (file, line number, header)
    for top in CHECKED_TOPS:
        for path in sorted((root / top).rglob("*")):
            if path.suffix not in (".cpp", ".hpp", ".h") or not path.is_file():
                continue
            rel = path.relative_to(root).as_posix()
            for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
                match = INCLUDE.match(line)
                if match:
                    includes.append((rel, number, match.group(1)))
    for plant in args.plant:
        file, header = plant.split(":", 1)
        includes.append((file, 0, header))

    problems = []
    unplaced = set()
    for file, number, header in includes:
        source = folder_of(file)
        if source is None:
            unplaced.add(file)
            continue
        if header.split("/")[0] not in CHECKED_TOPS:
            continue  # a system or third-party header
        target = folder_of(header)
        if target is None:
            unplaced.add(header)
            continue
        if rank[target] > rank[source]:
            problems.append(f"{file}:{number}: includes {header}: {target} is above {source}")
    for path in sorted(unplaced):
        problems.append(f"{path}: in no folder of the layer list (tests/scripts/layer_check.py)")
    for problem in problems:
        print(problem)
    print(f"{len(includes)} includes checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
