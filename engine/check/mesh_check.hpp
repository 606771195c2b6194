#pragma once
// Validity and conformity check of a hybrid mesh: what `tubemesh check` and the pipeline
// run before any file is written.
//
// Faces are matched by their node sets (sorted arrays of face records, no maps), so a 5 M
// cell mesh is checked in seconds. Volumes use plain double determinants: this is a report,
// not a decision that has to be exact.
#include <string>
#include <vector>

#include "engine/core/pulse.hpp"
#include "engine/mesh/hybrid_mesh.hpp"

namespace tubemesh {

enum class ViolationKind {
    NonPositiveVolume,      // tet signed volume, a pyramid base-corner tet, or a hex corner Jacobian <= 0
    DegenerateCell,         // a cell that repeats a node
    FaceSharedByMany,       // a face (same node set) on more than two cells
    SameOrientation,        // an interior face whose two cells see it with the same orientation
    NonMatchingFace,        // a quad facing triangles (or a triangle facing part of a quad)
    OpenBoundary,           // a boundary edge not on exactly two boundary faces
    BoundaryFaceNotOnCell,  // a stored boundary face that is not a free cell face with outward orientation
                            // (in an interface group, hybrid_mesh.hpp: not an interior face)
};

const char* violation_name(ViolationKind kind);

// A cell or stored boundary face, named by kind and index. The first three sets follow
// CellKind's order.
struct ElementRef {
    enum class Set { Tet, Pyramid, Hex, BoundaryTri, BoundaryQuad } set;
    index_t index;
    bool operator==(const ElementRef&) const = default;
};

// count is the number of distinct offending elements: a cell with two bad faces counts once,
// and a face problem between two cells (SameOrientation, a quad facing triangles) names both.
struct Violation {
    ViolationKind kind;
    index_t count = 0;
    std::vector<ElementRef> first;  // the 10 smallest offending elements, by set then index
    bool operator==(const Violation&) const = default;
};

struct CheckReport {
    std::vector<Violation> violations;  // only kinds that occurred, in ViolationKind order
    index_t interior_faces = 0;  // faces on exactly two cells
    index_t boundary_faces = 0;  // free cell faces (a face on one cell that no other face covers)
    double volume = 0;           // sum of cell volumes, see check_mesh
    double boundary_area = 0;    // area of the free cell faces, see check_mesh
    bool ok() const { return violations.empty(); }
    const Violation* find(ViolationKind kind) const;  // nullptr when the kind did not occur
    bool operator==(const CheckReport&) const = default;
};

// Parallel over cells where that helps; the report, volume and area included, does not depend
// on the thread count.
//
// Volumes are those of the cells with bilinear quad faces, so a conforming mesh sums to the
// volume its boundary encloses even where quads are not planar: a tet is its determinant / 6,
// a pyramid the cone from its apex over its base (the mean of the two diagonal splits), a hex
// the sum of the cones from its centroid over its six faces (the exact volume of the trilinear
// hex). All three equal the usual tet decompositions when the faces are planar.
// A quad's area is that of the smaller of its two diagonal splits: exact for any planar quad,
// convex or not; for a non-planar quad it is the flatter fold, not the bilinear surface.
//
// Cells that repeat a node are reported as DegenerateCell only and take no part in face
// matching. Free faces found to be NonMatchingFace are interior in spirit and are not
// boundary faces (so the same mismatch is not reported again as OpenBoundary).
// Throws tubemesh::Error when the layout is broken (HybridMesh::validate_layout) or the mesh
// has more than 2^31 triangular or 2^29 quadrilateral cell faces. `pulse` is called between
// the steps (engine/core/pulse.hpp).
CheckReport check_mesh(const HybridMesh& mesh, const Pulse& pulse = {});

// One line per violation kind ("NonPositiveVolume: 3 (tet 12, tet 40, pyramid 2)"), lines
// separated by '\n' without a trailing one; empty when the report is ok.
std::string describe(const CheckReport& report);

}  // namespace tubemesh
