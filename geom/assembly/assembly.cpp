#include "geom/assembly/assembly.hpp"

#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cmath>

#include "engine/core/types.hpp"
#include "geom/assembly/assembly_occt.hpp"
#include "geom/import/cad_readers.hpp"
#include "geom/import/solid_check.hpp"

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

// The centre and diagonal of a solid's vertices' box: the same for a copy, and fast (the
// boxes of a pipe's B-spline wall cost seconds).
std::pair<gp_Pnt, double> box_key(const TopoDS_Shape& s) {
    Bnd_Box box;
    for (TopExp_Explorer it(s, TopAbs_VERTEX); it.More(); it.Next()) box.Add(BRep_Tool::Pnt(TopoDS::Vertex(it.Current())));
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    return {gp_Pnt((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2), std::sqrt(box.SquareExtent())};
}

// Each solid's name in the file: the named solid it is, else the one whose box it has (the
// reader's healing may have copied it), else none.
std::vector<std::string> names_in(const CadFile& file, const std::vector<TopoDS_Solid>& solids) {
    std::vector<std::pair<gp_Pnt, double>> named;
    for (const auto& entry : file.names) named.push_back(box_key(entry.first));
    std::vector<std::string> out;
    for (const TopoDS_Solid& solid : solids) {
        std::string name;
        for (const auto& [shape, n] : file.names)
            if (shape.IsSame(solid)) name = n;
        if (name.empty() && !named.empty()) {
            const auto [centre, size] = box_key(solid);
            for (std::size_t i = 0; i < named.size() && name.empty(); ++i)
                if (named[i].first.Distance(centre) < 1e-9 * size && std::abs(named[i].second - size) < 1e-9 * size)
                    name = file.names[i].second;
        }
        out.push_back(name);
    }
    return out;
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
        std::vector<TopoDS_Solid> found;
        for (TopExp_Explorer it(file.shape, TopAbs_SOLID); it.More(); it.Next()) found.push_back(TopoDS::Solid(it.Current()));
        const std::vector<std::string> names = names_in(file, found);
        std::vector<NamedSolid> solids;
        for (std::size_t k = 0; k < found.size(); ++k) solids.push_back({found[k], names[k]});
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
