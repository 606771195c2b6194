#pragma once
// Importing a CAD file: the one solid tubemesh meshes, checked and safely healed.
#include <filesystem>

#include "geom/model/model.hpp"

namespace tubemesh::geom {

struct ImportOptions {
    // Which solid to mesh, 1-based, when the file holds several (the CLI's --solid N).
    // 0: the file must hold exactly one.
    int solid = 0;
    // Run ShapeFix_Shape (default precision) on the chosen solid; its changes go to the report.
    bool heal = true;
    // How the message for several solids names the ways out: the command line's (--solid N,
    // `tubemesh mesh --assembly`) or the Python module's keywords (solid=N, assembly=True).
    bool keyword_names = false;
};

// Reads a STEP (.step/.stp, AP203/214/242), IGES (.iges/.igs) or BREP (.brep) file and keeps the
// coordinates in the file's own unit (reported in Model::report().length_unit).
// Throws tubemesh::Error, with a message naming the file and what to do, when the file is missing
// or not CAD, holds no solid (only open shells or loose faces), holds several solids and no
// `solid` was chosen, or the chosen solid fails OpenCASCADE's validity check after healing.
Model import_model(const std::filesystem::path& path, const ImportOptions& options = {});

}  // namespace tubemesh::geom
