#pragma once
// geom::Model: the one solid tubemesh meshes, with its faces and edges numbered once.
//
// Ids are 1-based and stable for the life of the Model: face 3 is "face_3" in every report,
// mesh group and error message. OpenCASCADE types stay behind the pimpl; geom/ sources reach
// them through geom/model/model_occt.hpp.
#include <memory>
#include <string>
#include <vector>

#include "engine/mesh/hybrid_mesh.hpp"  // tubemesh::Vec3

namespace tubemesh::geom {

// Where a Model came from and what import did to it, for reports and --verbose output.
struct ImportReport {
    std::string source;       // the file path, or "builder: <preset>" for a built block
    std::string format;       // "STEP", "IGES", "BREP" or "built"
    // The solid's name: the one a STEP file gives it (make-block writes the preset's), or the
    // built block's preset or spec name; empty when the file names none.
    std::string name;
    std::string length_unit;  // as the file declares it ("millimetre", "metre", "inch"); "model units" for BREP
    int solids_in_file = 1;   // how many solids the file held
    int solid_index = 1;      // which one (1-based) this Model is
    std::vector<std::string> healing;  // what ShapeFix changed, one line each; empty when nothing
    std::vector<std::string> notes;    // other things worth telling the user (units kept, shells closed, ...)
    // Per face id (index id - 1), the name the file gives the face (STEP: its ADVANCED_FACE's,
    // as write_step writes a built block's "top", ...); empty, or shorter, where it gives none.
    std::vector<std::string> face_names;
};

struct BoundingBox {
    Vec3 min{0, 0, 0};
    Vec3 max{0, 0, 0};
};

class Model {
public:
    struct Impl;  // defined in geom/model/model_occt.hpp

    explicit Model(std::unique_ptr<Impl> impl);
    Model(Model&&) noexcept;
    Model& operator=(Model&&) noexcept;
    ~Model();

    int face_count() const;
    int edge_count() const;
    // "face_3", "edge_12": the names every tubemesh output uses for B-rep entities.
    static std::string face_name(int id);
    static std::string edge_name(int id);

    // Lengths, areas and volumes are the working space's (geom/working_scale.hpp): the source's
    // scaled by 10^-scale_exponent(). 0 (no scaling) for every model of diagonal 1 to 1000.
    double volume() const;  // of the solid, by OpenCASCADE's volume integration
    BoundingBox bounds() const;
    int scale_exponent() const;

    const ImportReport& report() const;

    const Impl& impl() const { return *impl_; }

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace tubemesh::geom
