#pragma once
// Block specs as JSON, for `tubemesh make-block --spec FILE`.
//
//   {
//     "name": "two pipes",                 optional; default: the file name
//     "unit": "metre",                     optional; default "model units"
//     "box": [6, 5, 3],                    or "cylinder": {"diameter": 295, "length": 300}
//     "pipes": [
//       {"path": "line", "diameter": 0.1, "points": [[0, 2, 1], [6, 2, 1]]},
//       {"path": "polyline", "diameter": 0.1, "bend_radius": 0.5,
//        "points": [[0, 4, 1], [3, 4, 1], [3, 4, 3]]},
//       {"path": "spline", "diameter": 0.1, "points": [[2, 0, 2], [2.5, 2, 2.2], [3, 5, 2]],
//        "start_tangent": [0, 1, 0]},                     tangents optional
//       {"path": "line", "diameter": 0.2, "points": [[2, 2, 0], [2, 2, 1]], "blind": true}
//     ],
//     "check_clearance": false             optional; default true
//   }
//
// "path" is one of line, arc (start, a point on the arc, end), polyline (corners rounded with
// bend_radius), spline (through the points) or bspline (control points); "pipes": [] is a block
// without pipes. Instead of "box" and "pipes", {"serpentine": {"size": [20, 15, 3], "diameter":
// 0.032, "spacing": 1.5, "bend_radius": 0.75, "end_margin": 1, "inlet": "x-", "outlet": "x-"}}
// describes a dam lift (every field optional, defaults as shown). Unknown keys are errors, so
// typos do not pass.
// A blind line ends at its second point, inside the block (a drilled hole). "check_clearance":
// false builds pipes that cross, touch or graze the boundary, which the builder otherwise
// refuses: hostile input for tubemesh's own geometry diagnosis.
#include <filesystem>
#include <string>

#include "geom/builders/block_spec.hpp"

namespace tubemesh::geom {

// Throws tubemesh::Error naming the file, the place in it and what is wrong.
BlockSpec read_block_spec(const std::filesystem::path& path);
BlockSpec parse_block_spec(const std::string& text, const std::string& source);

// The spec as JSON in the format above (a random block's spec, to reproduce or edit it).
std::string block_spec_json(const BlockSpec& spec);

}  // namespace tubemesh::geom
