#pragma once
// The OpenCASCADE side of geom::Assembly. geom/ sources only.
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Solid.hxx>

#include <string>
#include <vector>

#include "geom/assembly/assembly.hpp"

namespace tubemesh::geom {

struct Assembly::Impl {
    TopoDS_Shape compound;  // the glued solids, faces shared
    TopTools_IndexedMapOfShape faces, edges, vertices;  // assembly ids, 1-based
    std::vector<AssemblySolid> solids;
    std::vector<SharedFace> shared;
    AssemblyReport report;
};

struct NamedSolid {
    TopoDS_Solid solid;
    std::string name;  // empty: "solid_<k>"
};

// Glues the solids with the general fuse (BOPAlgo_Builder, fuzzy value `tolerance` > 0) and
// numbers the result. `report` arrives with source, format, unit and notes filled. Throws
// tubemesh::Error on an overlap or a gap wider than the tolerance (assembly.hpp).
Assembly glue_solids(const std::vector<NamedSolid>& solids, double tolerance, AssemblyReport report);

// The glued compound and each solid's name, for writing the assembly as STEP.
inline const TopoDS_Shape& compound_of(const Assembly& a) { return a.impl().compound; }

}  // namespace tubemesh::geom
