#pragma once
// What the HTML report's 3D view shows: the cells nearest to a plane through the middle of the
// first tube, normal to its axis, on one side of it — a cut through the hex ring, the pyramids
// and the tets around them, as in the paper's Fig. 5, 9 and 12 — reduced, kind by kind, to the
// faces not shared by two of its cells of that kind (each kind's surface, which the viewer shows
// or hides as a whole), plus every face of the worst cells (where their markers go).
//
// Coordinates are in the cut's frame: the plane is z = 0, the cells lie at z <= 0 (by their
// centroids, so cells crossing the plane are whole), x and y span the plane, and lengths are
// divided by `scale` (about the distance from the axis to the farthest cell shown). A mesh
// without tubes is cut through its bounding box's centre, normal to z.
#include <array>
#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>

#include "geom/mesh_file.hpp"

namespace tubemesh::job {

// At most this many cells: a few thousand keep the page small and the view legible.
inline constexpr std::size_t kCutCells = 3000;

// {"scale", "points": [x, y, z, ...], "cells": {"kind": [0 tet | 1 pyramid | 2 hex, ...],
//  "index": [...], "quality": [...]}, "faces": [cell, size, node..., ...],
//  "worst": [cell, ...] (the cut's lowest primary measure per kind, worst first)}.
// `primary` holds each kind's primary measure (quality_measures.hpp) per cell, by CellKind.
nlohmann::json cut_view_json(const geom::MeshRun& run, const std::array<std::vector<double>, kCellKindCount>& primary,
                             std::size_t max_cells = kCutCells);

}  // namespace tubemesh::job
