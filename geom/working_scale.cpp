#include "geom/working_scale.hpp"

#include <TopoDS.hxx>

#include <string>

#include "geom/mesh_file.hpp"
#include "geom/model/model_occt.hpp"
#include "geom/model/scale_factor_occt.hpp"

namespace tubemesh::geom {

namespace {

// from_working for a value of `dimension` 1 (a length), 2 (an area) or 3 (a volume); 0: none.
double rescale(double value, int k, int dimension) {
    for (int d = 0; d < dimension; ++d) value = from_working(value, k);
    return value;
}

void scale_points(std::vector<double>& v, int k) {
    for (double& x : v) x = from_working(x, k);
}

Vec3 scale_vec(const Vec3& p, int k) { return {from_working(p.x, k), from_working(p.y, k), from_working(p.z, k)}; }

// The phase statistics that are lengths (1), areas (2) or volumes (3); the others (quality
// measures, seconds) have no unit of length.
int statistic_dimension(const std::string& name) {
    if (name == "S" || name == "St" || name == "ring join gap") return 1;
    if (name == "boundary area") return 2;
    if (name == "volume") return 3;
    return 0;
}

}  // namespace

std::optional<Model> working_copy(const Model& model) {
    const int k = working_scale_exponent(solid_of(model));
    if (k == 0) return std::nullopt;
    return make_model(TopoDS::Solid(scaled_to_working(solid_of(model), k)), model.report(), std::nullopt,
                      model.scale_exponent() + k);
}

MeshOptions working_options(const MeshOptions& options, int k) {
    MeshOptions o = options;
    o.size = to_working(o.size, k);
    o.sweep_size = to_working(o.sweep_size, k);
    o.sweep.sweep_size = to_working(o.sweep.sweep_size, k);
    o.tets.far_size = to_working(o.tets.far_size, k);
    return o;
}

TubeSearch at_source_scale(TubeSearch found, int k) {
    if (k == 0) return found;
    for (TubeInfo& t : found.tubes) {
        for (double& l : t.loop_lengths) l = from_working(l, k);
        t.radius_min = from_working(t.radius_min, k);
        t.radius_max = from_working(t.radius_max, k);
        t.length = from_working(t.length, k);
        t.min_curvature_radius = from_working(t.min_curvature_radius, k);
        for (Vec3& p : t.centre_line) p = scale_vec(p, k);
    }
    return found;
}

SizePlan at_source_scale(SizePlan plan, int k) {
    if (k == 0) return plan;
    for (double* l : {&plan.size, &plan.sweep_size, &plan.initial_size, &plan.initial_sweep_size, &plan.dc, &plan.dcb,
                      &plan.rc, &plan.largest_sweep_size})
        *l = from_working(*l, k);
    for (SizeChange& c : plan.changes)
        for (double* l : {&c.old_sweep_size, &c.new_sweep_size, &c.old_size, &c.new_size}) *l = from_working(*l, k);
    return plan;
}

std::string working_scale_line(int k) {
    return "meshed scaled by 1e" + std::to_string(-k) +
           " (tubemesh meshes a solid of size 1 to 1000): every figure is in the source's unit except those inside "
           "the rules' reasons and the warnings' text, which are at that scale";
}

void scale_back(MeshRun& run, int k) {
    if (k == 0) return;
    PipelineResult& r = run.result;
    scale_points(r.mesh.x, k);
    scale_points(r.mesh.y, k);
    scale_points(r.mesh.z, k);
    r.check.volume = rescale(r.check.volume, k, 3);
    r.check.boundary_area = rescale(r.check.boundary_area, k, 2);
    for (PhaseReport& p : r.phases)
        for (auto& [name, value] : p.statistics) value = rescale(value, k, statistic_dimension(name));
    for (TubeRing& ring : r.sweep.rings) {
        ring.sweep_size = from_working(ring.sweep_size, k);
        ring.axial_step = from_working(ring.axial_step, k);
        for (RingEnd& end : ring.ends)
            for (Vec3& p : end.outer_xyz) p = scale_vec(p, k);
    }
    for (SizeSource& s : r.surface_size_caps) s = {scale_vec(s.point, k), from_working(s.size, k)};
    for (RingCoverage& c : run.coverage) {
        c.wall_area = rescale(c.wall_area, k, 2);
        c.thinnest = from_working(c.thinnest, k);
        c.thickest = from_working(c.thickest, k);
        c.ring_length = from_working(c.ring_length, k);
        c.length = from_working(c.length, k);
    }
    run.size = from_working(run.size, k);
    run.sweep_size = from_working(run.sweep_size, k);
}

}  // namespace tubemesh::geom
