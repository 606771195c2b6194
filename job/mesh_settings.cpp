#include "job/mesh_settings.hpp"

#include <fmt/format.h>

#include <cmath>

#include "geom/engine_grid.hpp"

namespace tubemesh::job {

namespace {

void require_positive(const std::optional<double>& value, const char* keyword, Naming naming) {
    if (value && !(*value > 0 && std::isfinite(*value)))
        throw Error(fmt::format("{} must be a positive number, got {}", option_name(keyword, naming), *value));
}

void require_in(double value, Range range, const char* keyword, Naming naming) {
    if (!(value >= range.lo && value <= range.hi))
        throw Error(fmt::format("{} must be between {} and {}, got {}", option_name(keyword, naming), range.lo, range.hi,
                                value));
}

}  // namespace

std::string option_name(const char* keyword, Naming naming) {
    if (naming == Naming::Keywords) return keyword;
    std::string flag = std::string("--") + keyword;
    for (char& c : flag)
        if (c == '_') c = '-';
    return flag;
}

const MeshOptions& default_mesh_options() {
    static const MeshOptions defaults;
    return defaults;
}

MeshOptions mesh_options(const MeshSettings& s, Naming naming) {
    require_positive(s.size, "size", naming);
    require_positive(s.sweep_size, "sweep_size", naming);
    if (s.size && s.sweep_size && !(*s.sweep_size < *s.size))
        throw Error(fmt::format("contradictory sizes: {} {} must be smaller than {} {}", option_name("sweep_size", naming),
                                *s.sweep_size, option_name("size", naming), *s.size));
    if (s.circumferential) require_in(*s.circumferential, kCircRange, "circ", naming);
    require_in(s.chordal, kChordalRange, "chordal", naming);
    require_in(s.layers, kLayersRange, "layers", naming);
    require_in(s.axial_aspect, kAxialAspectRange, "axial_aspect", naming);
    require_in(s.pyramid_height, kPyramidHeightRange, "pyramid_height", naming);
    require_in(s.gradation, kGradationRange, "gradation", naming);
    if (s.threads) require_in(*s.threads, kThreadsRange, "threads", naming);
    require_in(s.tet_parts, kTetPartsRange, "tet_parts", naming);
    require_in(s.tet_relax, kTetRelaxRange, "tet_relax", naming);
    require_positive(s.max_elements, "max_elements", naming);
    if (s.solid) require_in(*s.solid, kSolidRange, "solid", naming);

    MeshOptions o;
    o.size = s.size.value_or(0);
    o.sweep_size = s.sweep_size.value_or(0);
    o.sweep_share = s.sweep_share;
    o.local_ring = s.local_ring;
    o.grid_bits = s.scale_free ? geom::kScaleFreeGridBits : 0;
    o.circumferential = s.circumferential.value_or(0);
    o.chordal = s.chordal;
    o.chordal_given = s.chordal_given;
    o.sweep.radial_layers = s.layers;
    o.sweep.axial_aspect = s.axial_aspect;
    o.pyramids.height_factor = s.pyramid_height;
    o.tets.gradation = s.gradation;
    o.tet_parts = static_cast<unsigned>(s.tet_parts);
    o.tets.relaxation.iterations = s.tet_relax;
    o.tets.move_apexes = s.move_apexes;
    o.tets.slide_surface = s.slide_surface;
    o.threads = s.threads.value_or(0);
    o.max_elements = s.max_elements.value_or(0);
    return o;
}

void apply_economy(MeshSettings& s, GivenSettings given) {
    if (!s.circumferential) s.circumferential = kEconomy.circumferential;
    s.sweep_share = kEconomy.sweep_share;
    if (!given.layers) s.layers = kEconomy.layers;
    if (!given.axial_aspect) s.axial_aspect = kEconomy.axial_aspect;
    if (!given.chordal) s.chordal = kEconomy.chordal;
    s.local_ring = kEconomy.local_ring;
}

std::string stage_names() {
    std::string names;
    for (Stage s : kStages) names += (names.empty() ? "" : ", ") + std::string(stage_name(s));
    return names;
}

Stage stage_named(const std::string& name, Naming naming) {
    const std::optional<Stage> stage = stage_from_name(name);
    if (!stage) throw Error(option_name("until", naming) + " " + name + ": no such stage (use " + stage_names() + ")");
    return *stage;
}

}  // namespace tubemesh::job
