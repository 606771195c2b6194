#include "geom/assembly/dam_section.hpp"

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <TopoDS.hxx>
#include <gp_Trsf.hxx>

#include <fmt/format.h>

#include <cmath>

#include "geom/assembly/assembly_occt.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/import/step_write_occt.hpp"

namespace tubemesh::geom {

namespace {

// The glue tolerance of a built section, over its bounding-box diagonal: the blocks' faces
// coincide to rounding.
constexpr double kGlueShare = 1e-6;

}  // namespace

std::string dam_solid_name(const DamBlock& block) { return fmt::format("block_{}_{}", block.column, block.lift); }

Assembly build_dam_section(const std::vector<DamBlock>& blocks) {
    std::vector<NamedSolid> solids;
    Bnd_Box box;
    for (const DamBlock& b : blocks) {
        const BuiltBlock built = build_block(b.spec);
        gp_Trsf move;
        move.SetTranslation(gp_Vec(b.origin.x, b.origin.y, b.origin.z));
        const TopoDS_Solid solid = TopoDS::Solid(solid_of(built.model).Moved(TopLoc_Location(move)));
        BRepBndLib::AddOptimal(solid, box, false, false);
        solids.push_back({solid, dam_solid_name(b)});
    }
    AssemblyReport report;
    report.source = fmt::format("builder: dam section of {} blocks", blocks.size());
    report.format = "built";
    report.length_unit = blocks.empty() ? "model units" : blocks.front().spec.length_unit;
    return glue_solids(solids, kGlueShare * std::sqrt(box.SquareExtent()), std::move(report));
}

void write_assembly_step(const Assembly& assembly, const std::filesystem::path& path) {
    std::vector<NamedShape> names;
    for (const AssemblySolid& s : assembly.solids()) names.emplace_back(solid_of(s.model), s.name);
    write_step_shape(compound_of(assembly), path, assembly.report().length_unit, names);
}

}  // namespace tubemesh::geom
