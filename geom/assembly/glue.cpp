#include <BOPAlgo_Builder.hxx>
#include <BRepBndLib.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "engine/core/types.hpp"
#include "geom/assembly/assembly_occt.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/import/solid_check.hpp"

namespace tubemesh::geom {

namespace {

// Solids that nearly touch (closer than this share of the smaller one's bounding-box
// diagonal) but share no face are taken for a gap; farther apart they are separate bodies.
constexpr double kGapShare = 0.01;

double volume_of(const TopoDS_Shape& s) {
    GProp_GProps props;
    BRepGProp::VolumeProperties(s, props);
    return props.Mass();
}

// The box of a solid's vertices, grown by a tenth of its diagonal for faces that bulge past
// them: a cheap first look (a pipe's B-spline wall takes seconds to box exactly).
Bnd_Box box_of(const TopoDS_Shape& s) {
    Bnd_Box box;
    for (TopExp_Explorer it(s, TopAbs_VERTEX); it.More(); it.Next()) box.Add(BRep_Tool::Pnt(TopoDS::Vertex(it.Current())));
    if (!box.IsVoid()) box.Enlarge(0.1 * std::sqrt(box.SquareExtent()));
    return box;
}

double diagonal(const Bnd_Box& b) { return b.IsVoid() ? 0 : std::sqrt(b.SquareExtent()); }

TopoDS_Compound compound_of_solids(const std::vector<TopoDS_Solid>& solids) {
    TopoDS_Compound c;
    BRep_Builder builder;
    builder.MakeCompound(c);
    for (const TopoDS_Solid& s : solids) builder.Add(c, s);
    return c;
}

// Faces with two different solids among their ancestors.
int count_shared_faces(const TopoDS_Shape& compound) {
    TopTools_IndexedDataMapOfShapeListOfShape owners;
    TopExp::MapShapesAndUniqueAncestors(compound, TopAbs_FACE, TopAbs_SOLID, owners);
    int n = 0;
    for (int i = 1; i <= owners.Extent(); ++i) n += owners(i).Extent() == 2;
    return n;
}

std::vector<TopoDS_Solid> solid_images(const BOPAlgo_Builder& builder, const TopoDS_Solid& input) {
    std::vector<TopoDS_Solid> out;
    const TopTools_ListOfShape& modified = const_cast<BOPAlgo_Builder&>(builder).Modified(input);
    for (const TopoDS_Shape& s : modified)
        for (TopExp_Explorer it(s, TopAbs_SOLID); it.More(); it.Next()) out.push_back(TopoDS::Solid(it.Current()));
    if (out.empty() && !const_cast<BOPAlgo_Builder&>(builder).IsDeleted(input)) out.push_back(input);
    return out;
}

std::string pair_name(const std::vector<NamedSolid>& in, std::size_t i, std::size_t j) {
    return "'" + in[i].name + "' and '" + in[j].name + "'";
}

// An input the fuse cut into several solids overlaps another: the piece both keep is common.
void refuse_overlaps(const std::vector<NamedSolid>& in, const std::vector<std::vector<TopoDS_Solid>>& images,
                     double tolerance) {
    for (std::size_t i = 0; i < in.size(); ++i) {
        if (images[i].size() <= 1) continue;
        for (std::size_t j = 0; j < in.size(); ++j) {
            if (j == i) continue;
            for (const TopoDS_Solid& a : images[i])
                for (const TopoDS_Solid& b : images[j])
                    if (a.IsSame(b))
                        throw Error(fmt::format(
                            "solids {} overlap (a common volume of {:.6g}, deeper than the glue tolerance {:.3g}): "
                            "an assembly's solids may only touch; move them apart in the CAD tool or give a larger "
                            "--glue-tolerance",
                            pair_name(in, std::min(i, j), std::max(i, j)), volume_of(a), tolerance));
        }
        throw Error(fmt::format("solid '{}' was cut into {} pieces by the others when glued: the solids overlap by "
                                "more than the glue tolerance {:.3g}",
                                in[i].name, images[i].size(), tolerance));
    }
}

bool meet(const std::vector<int>& a, const std::vector<int>& b) {
    std::vector<int> common;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
    return !common.empty();
}

// The faces of `solid` whose boxes reach into `box`, as one compound.
TopoDS_Compound faces_near(const TopoDS_Solid& solid, const Bnd_Box& box) {
    TopoDS_Compound c;
    BRep_Builder builder;
    builder.MakeCompound(c);
    for (TopExp_Explorer it(solid, TopAbs_FACE); it.More(); it.Next()) {
        Bnd_Box face;
        BRepBndLib::Add(it.Current(), face);
        if (!face.IsOut(box)) builder.Add(c, it.Current());
    }
    return c;
}

// Two solids that touch nowhere (no vertex in common) but come closer than kGapShare of their
// size: a gap. Only the faces near the other solid are measured (a pipe's B-spline wall inside
// a block costs seconds in BRepExtrema and is never the nearest).
void refuse_gaps(const std::vector<NamedSolid>& in, const std::vector<TopoDS_Solid>& solids,
                 const std::vector<std::vector<int>>& faces_of, const std::vector<std::vector<int>>& vertices_of,
                 double tolerance) {
    std::vector<Bnd_Box> boxes;
    for (const TopoDS_Solid& s : solids) boxes.push_back(box_of(s));
    for (std::size_t i = 0; i < solids.size(); ++i)
        for (std::size_t j = i + 1; j < solids.size(); ++j) {
            const double limit = kGapShare * std::min(diagonal(boxes[i]), diagonal(boxes[j]));
            Bnd_Box near_i = boxes[i], near_j = boxes[j];
            near_i.Enlarge(limit);
            near_j.Enlarge(limit);
            if (near_i.IsOut(boxes[j]) || meet(faces_of[i], faces_of[j]) || meet(vertices_of[i], vertices_of[j]))
                continue;
            BRepExtrema_DistShapeShape distance(faces_near(solids[i], near_j), faces_near(solids[j], near_i));
            if (!distance.IsDone()) continue;
            const double d = distance.Value();
            if (d > tolerance && d < limit)
                throw Error(fmt::format(
                    "solids {} leave a gap of {:.6g} between them, wider than the glue tolerance {:.3g}: close it in "
                    "the CAD tool or give a --glue-tolerance above {:.3g}",
                    pair_name(in, i, j), d, tolerance, d));
        }
}

}  // namespace

Assembly glue_solids(const std::vector<NamedSolid>& input, double tolerance, AssemblyReport report) {
    if (input.empty()) throw Error("the assembly holds no solid");
    if (!(tolerance > 0)) throw Error(fmt::format("the glue tolerance must be positive, got {}", tolerance));
    std::vector<NamedSolid> in = input;
    for (std::size_t k = 0; k < in.size(); ++k)
        if (in[k].name.empty()) in[k].name = "solid_" + std::to_string(k + 1);

    auto impl = std::make_unique<Assembly::Impl>();
    std::vector<TopoDS_Solid> inputs;
    for (const NamedSolid& s : in) inputs.push_back(s.solid);
    const int shared_before = count_shared_faces(compound_of_solids(inputs));

    std::vector<TopoDS_Solid> solids;
    try {
        BOPAlgo_Builder builder;
        for (const TopoDS_Solid& s : inputs) builder.AddArgument(s);
        builder.SetFuzzyValue(tolerance);
        builder.SetNonDestructive(true);
        builder.SetRunParallel(false);
        builder.Perform();
        if (builder.HasErrors())
            throw Error(fmt::format("OpenCASCADE's general fuse could not glue the {} solids (tolerance {:.3g}): "
                                    "check that they are valid and only touch",
                                    in.size(), tolerance));
        std::vector<std::vector<TopoDS_Solid>> images;
        for (const TopoDS_Solid& s : inputs) images.push_back(solid_images(builder, s));
        refuse_overlaps(in, images, tolerance);
        for (std::size_t k = 0; k < in.size(); ++k) {
            if (images[k].empty())
                throw Error("solid '" + in[k].name + "' vanished when the solids were glued: it lies inside another");
            solids.push_back(images[k].front());
        }
    } catch (const Standard_Failure& e) {
        throw Error(std::string("cannot glue the solids: OpenCASCADE failed with \"") + e.GetMessageString() + "\"");
    }

    impl->compound = compound_of_solids(solids);
    TopExp::MapShapes(impl->compound, TopAbs_FACE, impl->faces);
    TopExp::MapShapes(impl->compound, TopAbs_EDGE, impl->edges);
    TopExp::MapShapes(impl->compound, TopAbs_VERTEX, impl->vertices);

    std::vector<std::vector<int>> faces_of, vertices_of;
    for (std::size_t k = 0; k < solids.size(); ++k) {
        const std::string problems = validity_problems(solids[k]);
        if (!problems.empty())
            throw Error("solid '" + in[k].name + "' is not valid after gluing (" + problems +
                        "): repair it in the CAD tool");
        ImportReport r;
        r.source = report.source;
        r.format = report.format;
        r.length_unit = report.length_unit;
        r.solids_in_file = static_cast<int>(in.size());
        r.solid_index = static_cast<int>(k + 1);
        AssemblySolid part{in[k].name, make_model(solids[k], std::move(r), volume_of(solids[k])), {}, {}, {}};
        for (int f = 1; f <= part.model.face_count(); ++f) part.face_ids.push_back(impl->faces.FindIndex(face_of(part.model, f)));
        for (int e = 1; e <= part.model.edge_count(); ++e) part.edge_ids.push_back(impl->edges.FindIndex(edge_of(part.model, e)));
        TopTools_IndexedMapOfShape vertices;
        TopExp::MapShapes(solids[k], TopAbs_VERTEX, vertices);
        for (int v = 1; v <= vertices.Extent(); ++v) part.vertex_ids.push_back(impl->vertices.FindIndex(vertices(v)));
        std::vector<int> sorted = part.face_ids;
        std::sort(sorted.begin(), sorted.end());
        faces_of.push_back(std::move(sorted));
        sorted = part.vertex_ids;
        std::sort(sorted.begin(), sorted.end());
        vertices_of.push_back(std::move(sorted));
        impl->solids.push_back(std::move(part));
    }
    refuse_gaps(in, solids, faces_of, vertices_of, tolerance);

    for (std::size_t i = 0; i < solids.size(); ++i)
        for (std::size_t j = i + 1; j < solids.size(); ++j) {
            std::vector<int> common;
            std::set_intersection(faces_of[i].begin(), faces_of[i].end(), faces_of[j].begin(), faces_of[j].end(),
                                  std::back_inserter(common));
            for (int f : common) impl->shared.push_back({f, static_cast<int>(i), static_cast<int>(j)});
        }
    std::sort(impl->shared.begin(), impl->shared.end(), [](const SharedFace& a, const SharedFace& b) { return a.face < b.face; });

    report.solids_in_file = static_cast<int>(in.size());
    report.glue_tolerance = tolerance;
    report.shared_faces = static_cast<int>(impl->shared.size());
    report.glued_faces = std::max(0, report.shared_faces - shared_before);
    impl->report = std::move(report);
    return Assembly(std::move(impl));
}

}  // namespace tubemesh::geom
