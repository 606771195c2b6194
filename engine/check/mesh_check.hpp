#pragma once
// Validity and conformity check of a hybrid mesh: what `tubemesh check` and the pipeline
// run before any file is written.
#include <string>
#include <vector>

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
};

const char* violation_name(ViolationKind kind);

// A cell or stored boundary face, named by kind and index.
struct ElementRef {
    enum class Set { Tet, Pyramid, Hex, BoundaryTri, BoundaryQuad } set;
    index_t index;
};

struct Violation {
    ViolationKind kind;
    index_t count = 0;
    std::vector<ElementRef> first;  // up to 10 offending elements, in a deterministic order
};

struct CheckReport {
    std::vector<Violation> violations;  // only kinds that occurred, in ViolationKind order
    index_t interior_faces = 0;
    index_t boundary_faces = 0;  // free cell faces
    double volume = 0;           // sum of cell volumes
    double boundary_area = 0;    // area of the free cell faces
    bool ok() const { return violations.empty(); }
};

// Parallel over cells where that helps; the report does not depend on the thread count.
CheckReport check_mesh(const HybridMesh& mesh);

// One line per violation kind ("NonPositiveVolume: 3 (tet 12, tet 40, pyramid 2)").
std::string describe(const CheckReport& report);

}  // namespace tubemesh
