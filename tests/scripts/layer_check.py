#!/usr/bin/env python3
"""Fails on an include from a lower folder into a higher one (docs/architecture.md, "Layers").

Every source folder has a rank in LAYERS; a file may include project headers of its own folder
and of folders ranked below it. A folder's own files rank above its subfolders (the subfolders
are its parts). With --targets (the build's list of each target's sources and header file
sets), a file may also include another target's header only if that target publishes it (its
FILE_SET HEADERS). A header belongs to the target whose file set names it, else to the target
compiling the .cpp of the same name, else to the one target compiling sources in its folder.
--plant FILE:HEADER adds an include that is not in the tree, so a test can show the check fails.
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


def read_targets(path, root):
    """{target: (files it compiles, headers it publishes, headers it keeps)} from the build."""
    targets = {}
    for line in pathlib.Path(path).read_text().splitlines():
        if not line.strip():
            continue
        name, source_dir, *sets = line.split("\t")

        def files(text):
            out = set()
            for item in filter(None, text.split(";")):
                p = pathlib.Path(item if pathlib.Path(item).is_absolute() else pathlib.Path(source_dir) / item)
                try:
                    out.add(p.resolve().relative_to(root.resolve()).as_posix())
                except ValueError:
                    pass  # a generated file
            return out
        targets[name] = tuple(files(s) for s in sets)
    return targets


class Owners:
    def __init__(self, targets):
        self.published = {h: t for t, (_, public, _) in targets.items() for h in public}
        self.named = dict(self.published)
        self.named.update({h: t for t, (_, _, private) in targets.items() for h in private})
        self.compiled = {f: t for t, (sources, _, _) in targets.items() for f in sources}
        self.folder = {}
        for f, t in self.compiled.items():
            self.folder.setdefault(str(pathlib.PurePosixPath(f).parent), set()).add(t)

    def of(self, path):
        if path in self.named:
            return self.named[path]
        if path in self.compiled:
            return self.compiled[path]
        same = str(pathlib.PurePosixPath(path).with_suffix(".cpp"))
        if same in self.compiled:
            return self.compiled[same]
        folder = self.folder.get(str(pathlib.PurePosixPath(path).parent), set())
        return next(iter(folder)) if len(folder) == 1 else None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("root", help="the source tree")
    parser.add_argument("--plant", action="append", default=[], metavar="FILE:HEADER",
                        help="check as if FILE also included HEADER")
    parser.add_argument("--targets", metavar="FILE",
                        help="the build's target list (tests/CMakeLists.txt writes it): check published headers too")
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

    owners = Owners(read_targets(args.targets, root)) if args.targets else None
    problems = []
    unplaced = set()
    unowned = set()
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
        if owners is None:
            continue
        owner = owners.of(header)
        if owner is None:
            unowned.add(header)
        elif owners.published.get(header) != owner and owners.of(file) != owner:
            problems.append(f"{file}:{number}: includes {header}: not published by {owner} "
                            f"(its FILE_SET HEADERS)")
    for path in sorted(unplaced):
        problems.append(f"{path}: in no folder of the layer list (tests/scripts/layer_check.py)")
    for path in sorted(unowned):
        problems.append(f"{path}: no target owns it (name it in a target's header file set)")
    for problem in problems:
        print(problem)
    print(f"{len(includes)} includes checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
