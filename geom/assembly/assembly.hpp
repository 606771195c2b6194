#pragma once
// geom::Assembly: several solids that share faces (a dam section's lift blocks), glued into one
// non-manifold compound, with one face and edge numbering over all of them.
//
// Every face is numbered once (1-based, TopExp order over the glued compound): a face two solids
// share is one face, known with both solids. Each solid is also a geom::Model of its own, with
// its own local numbering (what tube recognition and sizing work on); `face_ids` / `edge_ids`
// carry a local id to the assembly's. No OpenCASCADE header here (geom/assembly/assembly_occt.hpp).
#include <memory>
#include <string>
#include <vector>

#include "geom/model/model.hpp"

namespace tubemesh::geom {

struct AssemblySolid {
    std::string name;  // from the file (STEP), else "solid_<k>"
    Model model;       // the solid alone, its faces and edges numbered locally
    // Local id i (1-based) -> assembly id face_ids[i - 1] / edge_ids[i - 1] / vertex_ids[i - 1]
    // (vertices in TopExp order on the solid, as geom/discretize_edges numbers them).
    std::vector<int> face_ids;
    std::vector<int> edge_ids;
    std::vector<int> vertex_ids;
};

// A face of two solids (0-based indices into Assembly::solids, first < second).
struct SharedFace {
    int face = 0;
    int first = 0, second = 0;
};

struct AssemblyReport {
    std::string source, format, length_unit;
    int solids_in_file = 0;
    double glue_tolerance = 0;  // the general fuse's fuzzy value, in model units
    int shared_faces = 0;       // after gluing
    // Faces that coincided within the tolerance without being one face in the file, and were
    // made one by the glue (0 for a file written already fragmented).
    int glued_faces = 0;
    std::vector<std::string> notes;
};

class Assembly {
public:
    struct Impl;  // geom/assembly/assembly_occt.hpp

    explicit Assembly(std::unique_ptr<Impl> impl);
    Assembly(Assembly&&) noexcept;
    Assembly& operator=(Assembly&&) noexcept;
    ~Assembly();

    const std::vector<AssemblySolid>& solids() const;
    const std::vector<SharedFace>& shared_faces() const;
    int face_count() const;
    int edge_count() const;
    const AssemblyReport& report() const;
    BoundingBox bounds() const;

    const Impl& impl() const { return *impl_; }

private:
    std::unique_ptr<Impl> impl_;
};

struct AssemblyOptions {
    // Faces of different solids closer than this coincide and are glued; 0 (default): 1e-6 of
    // the assembly's bounding-box diagonal.
    double glue_tolerance = 0;
};

// Reads a STEP, IGES or BREP file with several solids (one is fine) and glues them with
// OpenCASCADE's general fuse. Throws tubemesh::Error, naming the solids and the distance,
// when two solids overlap by more than the tolerance or leave a gap wider than it where they
// nearly touch (closer than 1 % of the smaller one's size), and for every import error
// (geom/import.hpp).
Assembly import_assembly(const std::string& path, const AssemblyOptions& options = {});

}  // namespace tubemesh::geom
