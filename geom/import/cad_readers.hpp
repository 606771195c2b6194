#pragma once
// Reading STEP, IGES and BREP files into one OpenCASCADE shape, in the file's own units.
// geom/ only; geom/import/import.hpp is the public entry point.
#include <TopoDS_Shape.hxx>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace tubemesh::geom {

enum class CadFormat { Step, Iges, Brep };

const char* format_name(CadFormat format);

// By extension (.step .stp .p21, .iges .igs, .brep .brp, any case), else by the first bytes.
// Throws tubemesh::Error when the file is missing or none of the three.
CadFormat detect_cad_format(const std::filesystem::path& path);

struct CadFile {
    TopoDS_Shape shape;               // everything the file holds, as one (compound) shape
    std::string length_unit;          // as declared, e.g. "millimetre"; "model units" for BREP
    std::vector<std::string> notes;   // unit remarks for the import report
    // STEP only: the solids the file names (their MANIFOLD_SOLID_BREP's name), in file order, as
    // the translator made them: the reader's healing may hand `shape` copies of them.
    std::vector<std::pair<TopoDS_Shape, std::string>> names;
    // STEP only: the faces the file names, as the translator made them.
    std::vector<std::pair<TopoDS_Shape, std::string>> face_names;
    // `shape` is the file's scaled by 10^-scale_exponent (geom/working_scale.hpp).
    int scale_exponent = 0;
};

// Coordinates are kept as written in the file: the readers' conversion to millimetres is
// cancelled, so a 15 x 25 x 4 block written in metres imports as 15 x 25 x 4. A file whose
// bounding-box diagonal is outside 1 to 1000 is read at working scale instead.
// Throws tubemesh::Error when the file cannot be read or holds no shape.
CadFile read_cad_file(const std::filesystem::path& path, CadFormat format);

}  // namespace tubemesh::geom
