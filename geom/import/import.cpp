#include "geom/import/import.hpp"

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <ShapeFix_Solid.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shell.hxx>

#include <fmt/format.h>

#include <optional>
#include <string>
#include <vector>

#include "engine/core/types.hpp"
#include "geom/import/cad_readers.hpp"
#include "geom/import/heal.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/import/solid_check.hpp"

namespace tubemesh::geom {

namespace {

std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

std::string plural(int n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::vector<TopoDS_Solid> solids_in(const TopoDS_Shape& shape) {
    std::vector<TopoDS_Solid> out;
    for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next()) out.push_back(TopoDS::Solid(it.Current()));
    return out;
}

int count(const TopoDS_Shape& shape, TopAbs_ShapeEnum type, TopAbs_ShapeEnum outside = TopAbs_SHAPE) {
    int n = 0;
    for (TopExp_Explorer it(shape, type, outside); it.More(); it.Next()) ++n;
    return n;
}

// A file without solids may still describe one as surfaces: closed shells (some exporters
// write solids that way) or faces that sew into closed shells (IGES trimmed surfaces). Those
// become solids, said in the notes; anything left open is an error that says what was found.
std::vector<TopoDS_Solid> solids_from_surfaces(const TopoDS_Shape& shape, const std::filesystem::path& path,
                                               std::vector<std::string>& notes) {
    const int faces = count(shape, TopAbs_FACE);
    if (faces == 0)
        throw Error(quoted(path) + " holds no solid and no surface (only " +
                    (count(shape, TopAbs_EDGE) > 0 ? "curves" : "points or empty groups") +
                    "): tubemesh needs one closed solid");

    BRepBuilderAPI_Sewing sewing;
    sewing.Add(shape);
    sewing.Perform();
    const TopoDS_Shape sewn = sewing.SewedShape();

    std::vector<TopoDS_Solid> out;
    int open_shells = 0;
    for (TopExp_Explorer it(sewn, TopAbs_SHELL); it.More(); it.Next()) {
        const TopoDS_Shell shell = TopoDS::Shell(it.Current());
        if (!BRep_Tool::IsClosed(shell)) {
            ++open_shells;
            continue;
        }
        // SolidFromShell rather than MakeSolid: it also turns an inside-out shell around.
        ShapeFix_Solid orient;
        const TopoDS_Shape fixed = orient.SolidFromShell(shell);
        for (const TopoDS_Solid& s : solids_in(fixed)) out.push_back(s);
    }
    const int loose_faces = count(sewn, TopAbs_FACE, TopAbs_SHELL);
    if (out.empty()) {
        std::string found = open_shells > 0 ? plural(open_shells, "open shell", "open shells") : "";
        if (loose_faces > 0) found += (found.empty() ? "" : " and ") + plural(loose_faces, "loose face", "loose faces");
        throw Error(quoted(path) + " holds no solid, only " + found + " (" + plural(faces, "face", "faces") +
                    " that do not close up): tubemesh needs one closed solid; close the surfaces into a solid in the "
                    "CAD tool and export it again");
    }
    notes.push_back("the file holds surfaces, not solids: " + plural(faces, "face was", "faces were") +
                    " sewn into " + plural(static_cast<int>(out.size()), "closed solid", "closed solids"));
    if (open_shells > 0 || loose_faces > 0)
        notes.push_back("ignored what did not close up: " + plural(open_shells, "open shell", "open shells") + ", " +
                        plural(loose_faces, "loose face", "loose faces"));
    return out;
}

// The name the file gives `solid`: its own entry, or the file's only name when it holds one
// solid (the reader's healing may have handed over a copy of the named shape).
std::string solid_name(const CadFile& file, const TopoDS_Shape& solid, int solids) {
    for (const auto& [shape, name] : file.names)
        if (shape.IsSame(solid)) return name;
    return solids == 1 && file.names.size() == 1 ? file.names.front().second : std::string();
}

// Per face of `solid` in TopExp order (its Model face ids), the name the file gives it. Healing
// that rebuilt a face loses its name.
std::vector<std::string> face_names_of(const CadFile& file, const TopoDS_Shape& solid) {
    std::vector<std::string> out;
    if (file.face_names.empty()) return out;
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solid, TopAbs_FACE, faces);
    out.resize(static_cast<std::size_t>(faces.Extent()));
    for (const auto& [shape, name] : file.face_names)
        if (const int id = faces.FindIndex(shape); id > 0) out[static_cast<std::size_t>(id - 1)] = name;
    return out;
}

}  // namespace

Model import_model(const std::filesystem::path& path, const ImportOptions& options) {
    const CadFormat format = detect_cad_format(path);
    CadFile file = read_cad_file(path, format);

    ImportReport report;
    report.source = path.string();
    report.format = format_name(format);
    report.length_unit = file.length_unit;
    report.notes = std::move(file.notes);
    const int scale_exponent = file.scale_exponent;
    if (scale_exponent != 0)
        report.notes.push_back(fmt::format("read scaled by 1e{} (tubemesh meshes a solid of size 1 to 1000); the mesh "
                                           "and the report are in the file's unit",
                                           -scale_exponent));

    try {
        std::vector<TopoDS_Solid> solids = solids_in(file.shape);
        if (solids.empty()) {
            solids = solids_from_surfaces(file.shape, path, report.notes);
        } else if (const int loose = count(file.shape, TopAbs_FACE, TopAbs_SOLID); loose > 0) {
            report.notes.push_back("ignored " + plural(loose, "face", "faces") + " outside the file's solids");
        }

        const int n = static_cast<int>(solids.size());
        report.solids_in_file = n;
        if (options.solid == 0 && n > 1)
            throw Error(quoted(path) + " holds " + std::to_string(n) + " solids: choose one with " +
                        (options.keyword_names ? "solid=N" : "--solid N") + " (N from 1 to " + std::to_string(n) +
                        "), or mesh them all as one conforming mesh with " +
                        (options.keyword_names ? "assembly=True" : "`tubemesh mesh --assembly`"));
        if (options.solid < 0 || options.solid > n)
            throw Error((options.keyword_names ? "solid=" : "--solid ") + std::to_string(options.solid) +
                        " is out of range: " + quoted(path) + " holds " +
                        plural(n, "solid", "solids") + " (N from 1 to " + std::to_string(n) + ")");
        report.solid_index = options.solid == 0 ? 1 : options.solid;

        TopoDS_Shape chosen = solids[static_cast<std::size_t>(report.solid_index - 1)];
        report.name = solid_name(file, chosen, n);
        bool healing_ran = false;
        if (options.heal) {
            if (std::optional<TopoDS_Shape> h = heal_shape(chosen, report.healing)) {
                chosen = *h;
                healing_ran = true;
            }
        }

        // Healing may hand back the solid wrapped in a compound; it must still be one solid.
        const std::vector<TopoDS_Solid> final_solids = solids_in(chosen);
        if (final_solids.size() != 1)
            throw Error("solid " + std::to_string(report.solid_index) + " of " + quoted(path) + " became " +
                        std::to_string(final_solids.size()) + " solids when healed: repair it in the CAD tool");
        const std::string problems = validity_problems(final_solids.front());
        if (!problems.empty())
            throw Error("solid " + std::to_string(report.solid_index) + " of " + quoted(path) + " is not a valid solid" +
                        (healing_ran ? " even after healing" : options.heal ? " and healing it failed" : "") + " (" +
                        problems + "): repair it in the CAD tool or export it again");

        report.face_names = face_names_of(file, final_solids.front());
        GProp_GProps props;
        BRepGProp::VolumeProperties(final_solids.front(), props);
        if (props.Mass() <= 0)
            throw Error("solid " + std::to_string(report.solid_index) + " of " + quoted(path) +
                        " has no positive volume (it is empty or inside out): repair it in the CAD tool");
        return make_model(final_solids.front(), std::move(report), props.Mass(), scale_exponent);
    } catch (const Standard_Failure& e) {
        throw Error("cannot import " + quoted(path) + ": OpenCASCADE failed with \"" + e.GetMessageString() + "\"");
    }
}

}  // namespace tubemesh::geom
