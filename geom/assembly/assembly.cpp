#include "geom/assembly/assembly.hpp"

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cmath>

#include "engine/core/types.hpp"
#include "geom/assembly/assembly_occt.hpp"
#include "geom/cad_readers.hpp"
#include "geom/solid_check.hpp"

namespace tubemesh::geom {

Assembly::Assembly(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Assembly::Assembly(Assembly&&) noexcept = default;
Assembly& Assembly::operator=(Assembly&&) noexcept = default;
Assembly::~Assembly() = default;

const std::vector<AssemblySolid>& Assembly::solids() const { return impl_->solids; }
const std::vector<SharedFace>& Assembly::shared_faces() const { return impl_->shared; }
int Assembly::face_count() const { return impl_->faces.Extent(); }
int Assembly::edge_count() const { return impl_->edges.Extent(); }
const AssemblyReport& Assembly::report() const { return impl_->report; }

BoundingBox Assembly::bounds() const {
    Bnd_Box box;
    BRepBndLib::AddOptimal(impl_->compound, box, false, false);
    BoundingBox b;
    box.Get(b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z);
    return b;
}

namespace {

// Relative to the bounding-box diagonal when the user gives none (assembly.hpp).
constexpr double kDefaultGlueShare = 1e-6;

gp_Pnt box_centre(const TopoDS_Shape& s, double& diagonal) {
    Bnd_Box box;
    BRepBndLib::AddOptimal(s, box, false, false);
    diagonal = std::sqrt(box.SquareExtent());
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    return gp_Pnt((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2);
}

// The file's name for a solid: the named one it is, else the one whose bounding box it fills
// (the reader's healing may have copied it), else none.
std::string name_in(const CadFile& file, const TopoDS_Shape& solid) {
    for (const auto& [shape, name] : file.names)
        if (shape.IsSame(solid)) return name;
    double size = 0, other = 0;
    const gp_Pnt centre = box_centre(solid, size);
    for (const auto& [shape, name] : file.names)
        if (box_centre(shape, other).Distance(centre) < 1e-6 * size && std::abs(other - size) < 1e-6 * size) return name;
    return {};
}

}  // namespace

Assembly import_assembly(const std::string& path, const AssemblyOptions& options) {
    const CadFormat format = detect_cad_format(path);
    CadFile file = read_cad_file(path, format);
    AssemblyReport report;
    report.source = path;
    report.format = format_name(format);
    report.length_unit = file.length_unit;
    report.notes = std::move(file.notes);
    try {
        std::vector<NamedSolid> solids;
        for (TopExp_Explorer it(file.shape, TopAbs_SOLID); it.More(); it.Next())
            solids.push_back({TopoDS::Solid(it.Current()), name_in(file, it.Current())});
        if (solids.empty())
            throw Error("'" + path + "' holds no solid: an assembly is a file of solids that share faces");
        double tolerance = options.glue_tolerance;
        if (tolerance < 0 || !std::isfinite(tolerance))
            throw Error("the glue tolerance must be a positive number (0: automatic)");
        if (tolerance == 0) {
            Bnd_Box box;
            BRepBndLib::AddOptimal(file.shape, box, false, false);
            tolerance = kDefaultGlueShare * std::sqrt(box.SquareExtent());
        }
        return glue_solids(solids, tolerance, std::move(report));
    } catch (const Standard_Failure& e) {
        throw Error("cannot import '" + path + "' as an assembly: OpenCASCADE failed with \"" + e.GetMessageString() + "\"");
    }
}

}  // namespace tubemesh::geom
