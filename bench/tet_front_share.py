#!/usr/bin/env python3
"""Tet collapse by how many corners a tet shares with the front, from a mesh file.

    /usr/bin/python3 bench/tet_front_share.py MESH.msh [...]

The front is every node of a surface triangle or quad, pyramid or hexahedron: what the tet step
starts from and (but for the apexes and flat-face nodes the optimisation may move) cannot move.
A tet with no front corner is as free as the optimisation gets; the shares show how much of a
mesh's mean the front decides. Collapse as engine/quality/quality.hpp defines it.
"""
import sys

import meshio
import numpy as np


def collapse(p):
    e1, e2, e3 = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0], p[:, 3] - p[:, 0]
    three_volume = 0.5 * np.einsum("ij,ij->i", e1, np.cross(e2, e3))
    area4 = np.stack([np.sum(np.cross(p[:, 2] - p[:, 1], p[:, 3] - p[:, 1]) ** 2, 1),
                      np.sum(np.cross(e2, e3) ** 2, 1), np.sum(np.cross(e1, e3) ** 2, 1),
                      np.sum(np.cross(e1, e2) ** 2, 1)])
    area = 0.5 * np.sqrt(np.where(three_volume < 0, area4.min(0), area4.max(0)))
    regular = np.sqrt(2 / 3) / np.sqrt(np.sqrt(3) / 4)
    return three_volume / (area * np.sqrt(area)) / regular


def main():
    for path in sys.argv[1:]:
        m = meshio.read(path)
        tets = np.vstack([c.data for c in m.cells if c.type == "tetra"])
        front = np.zeros(len(m.points), bool)
        for c in m.cells:
            if c.type in ("triangle", "quad", "pyramid", "hexahedron"):
                front[c.data.ravel()] = True
        q = collapse(m.points[tets])
        corners = front[tets].sum(1)
        print(f"{path}: {len(tets)} tets, collapse mean {q.mean():.4f}, min {q.min():.4f}")
        for k in range(5):
            s = corners == k
            if s.any():
                print(f"  {k} front corners: {100 * s.mean():5.1f} %  mean {q[s].mean():.4f}  min {q[s].min():.4f}")


if __name__ == "__main__":
    main()
