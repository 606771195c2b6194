#include "engine/pyramids/build_pyramids.hpp"

#include <algorithm>
#include <memory>
#include <string>

#include "engine/pyramids/advancing_front.hpp"
#include "engine/pyramids/face_tree.hpp"
#include "engine/pyramids/front_state.hpp"
#include "engine/pyramids/fronts.hpp"
#include "engine/pyramids/visible.hpp"

namespace tubemesh {

const char* verdict_name(Verdict v) {
    switch (v) {
        case Verdict::Accepted:
            return "accepted";
        case Verdict::AngleTooLarge:
            return "angle too large";
        case Verdict::NotPositive:
            return "not positive";
        case Verdict::LowQuality:
            return "low quality";
        case Verdict::FaceMismatch:
            return "face mismatch";
        case Verdict::PinchesFront:
            return "pinches the front";
        case Verdict::TooCloseToFace:
            return "too close to a face";
        case Verdict::ContainsNode:
            return "contains a node";
        case Verdict::TooCloseToEdge:
            return "too close to an edge";
        case Verdict::EdgeCrossesFace:
            return "new edge crosses a face";
        case Verdict::FaceCrossesEdge:
            return "new face crosses an edge";
    }
    return "?";
}

namespace {

using namespace pyramids;

// Two front quads on the same four nodes would get two pyramids in one place.
void check_fronts_distinct(std::span<const index_t> quads) {
    std::vector<std::pair<std::array<index_t, 4>, index_t>> sorted(quads.size() / 4);
    for (std::size_t i = 0; i < sorted.size(); ++i) {
        std::array<index_t, 4> q{quads[4 * i], quads[4 * i + 1], quads[4 * i + 2], quads[4 * i + 3]};
        std::sort(q.begin(), q.end());
        sorted[i] = {q, static_cast<index_t>(i)};
    }
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 1; i < sorted.size(); ++i)
        if (sorted[i].first == sorted[i - 1].first)
            throw Error("pyramids: front quads " + std::to_string(sorted[i - 1].second) + " and " +
                        std::to_string(sorted[i].second) + " have the same four nodes");
}

void check_input(const HybridMesh& mesh, const PyramidInput& in, const PyramidOptions& opt) {
    auto check = [&](std::span<const index_t> nodes, std::size_t stride, const char* what) {
        if (nodes.size() % stride != 0)
            throw Error(std::string("pyramids: ") + what + " hold " + std::to_string(nodes.size()) +
                        " node ids, not a multiple of " + std::to_string(stride));
        for (std::size_t i = 0; i < nodes.size(); ++i)
            if (nodes[i] >= mesh.point_count())
                throw Error(std::string("pyramids: ") + what + " " + std::to_string(i / stride) + " refers to node " +
                            std::to_string(nodes[i]) + " but the mesh has " + std::to_string(mesh.point_count()) +
                            " points");
    };
    check(in.front_quads, 4, "front quads");
    check(in.boundary_triangles, 3, "boundary triangles");
    check(in.obstacle_quads, 4, "obstacle quads");
    if (in.region >= mesh.region_names.size())
        throw Error("pyramids: region id " + std::to_string(in.region) +
                    " has no name in the mesh; create it with HybridMesh::region_id first");
    if (in.front_quads.size() / 4 >= kBoundaryOwner / 4 || in.boundary_triangles.size() / 3 >= kBoundaryOwner)
        throw Error("pyramids: more than 500 million fronts or 2 billion boundary triangles");
    if (!(opt.height_factor > 0) || !(opt.search_radius_factor >= 0) || !(opt.max_angle_degrees > 0) ||
        !(opt.distance_factor >= 0) || !(opt.relax_rate > 0 && opt.relax_rate <= 1) || opt.try_nodes < 0 ||
        opt.try_nodes > 8 || opt.max_drawback_rounds < 0 || !(opt.min_quality_ratio >= 0) ||
        !(opt.wedge_degrees >= 0 && opt.wedge_degrees < 90) || !(opt.wedge_height_factor > 0) ||
        !(opt.wedge_max_shift >= 0 && opt.wedge_max_shift < 0.5) ||
        !(opt.wedge_wide_shift >= 0 && opt.wedge_wide_shift < 1) || !(opt.apart_factor >= 0) ||
        !(opt.apart_lowest > 0 && opt.apart_lowest <= 1))
        throw Error(
            "pyramids: options out of range (height_factor > 0, relax_rate in (0, 1], try_nodes in 0..8, "
            "wedge_degrees in [0, 90), wedge_height_factor > 0, wedge_max_shift in [0, 0.5), "
            "wedge_wide_shift in [0, 1), apart_lowest in (0, 1], "
            "factors and rounds not negative)");
    check_fronts_distinct(in.front_quads);
}

std::vector<Box> fixed_face_boxes(const HybridMesh& mesh, const PyramidInput& in) {
    std::vector<Box> boxes;
    auto add = [&](std::span<const index_t> nodes, std::size_t stride) {
        for (std::size_t i = 0; i < nodes.size(); i += stride) {
            Box b = Box::of(mesh.point(nodes[i]));
            for (std::size_t k = 1; k < stride; ++k) b.add(mesh.point(nodes[i + k]));
            boxes.push_back(b);
        }
    };
    add(in.boundary_triangles, 3);
    add(in.obstacle_quads, 4);
    return boxes;
}

// Appends the used apexes (creation order) and the pyramids (front order) to the mesh and
// lists the free triangles (reversed: out of the tet region).
void append_to_mesh(HybridMesh& mesh, std::span<const Front> fronts, const FrontState& state,
                    std::size_t boundary_count, index_t region, PyramidResult& result) {
    const index_t base = state.mesh_points();
    std::vector<index_t> renumber(state.apexes().size(), kNoIndex);
    result.first_apex = mesh.point_count();
    for (std::size_t k = 0; k < state.apexes().size(); ++k) {
        if (state.apex_uses(static_cast<index_t>(k)) == 0) continue;
        const Vec3& p = state.apexes()[k];
        renumber[k] = mesh.add_point(p.x, p.y, p.z);
    }
    auto final_id = [&](index_t n) { return n < base ? n : renumber[n - base]; };

    PyramidStats& s = result.stats;
    result.first_pyramid = mesh.cell_count(CellKind::Pyramid);
    auto& block = mesh.block(CellKind::Pyramid);
    block.nodes.reserve(block.nodes.size() + 5 * fronts.size());
    block.region.reserve(block.region.size() + fronts.size());
    for (index_t i = 0; i < fronts.size(); ++i) {
        const auto& q = fronts[i].node;
        const std::array<index_t, 5> nodes{q[0], q[1], q[2], q[3], final_id(state.apex(i))};
        mesh.add_cell(CellKind::Pyramid, nodes, region);
        const std::uint8_t how = state.how(i);
        if (fronts[i].wedge) ++s.wedge_fronts;
        if (fronts[i].lowered) ++s.lowered;
        if (how == kHowIdeal)
            ++s.ideal;
        else if (how == kHowWide)
            ++s.wide;
        else if (how == kHowExisting)
            ++s.existing;
        else if (how == kHowExistingRelaxed)
            ++s.existing_relaxed;
        else if (how >= kHowMovedTryBase) {
            ++s.try_node[how - kHowMovedTryBase];
            ++s.moved_try_nodes;
        } else if (how >= kHowTryBase)
            ++s.try_node[how - kHowTryBase];
        for (int f = 0; f < 4; ++f) {
            if (!state.lateral_free(i, f)) {
                ++s.shared_triangles;  // counted from both sides, halved below
                continue;
            }
            const Triangle t = state.lateral(i, f);
            result.free_triangles.insert(result.free_triangles.end(), {final_id(t[1]), final_id(t[0]), final_id(t[2])});
        }
    }
    for (std::size_t b = 0; b < boundary_count; ++b)
        if (!state.boundary_free(static_cast<index_t>(b)))
            result.covered_boundary_triangles.push_back(static_cast<index_t>(b));
    s.covered_boundary_triangles = static_cast<index_t>(result.covered_boundary_triangles.size());
    s.shared_triangles = (s.shared_triangles - s.covered_boundary_triangles) / 2;
    s.pyramids = static_cast<index_t>(fronts.size());
}

}  // namespace

PyramidResult build_pyramids(HybridMesh& mesh, const PyramidInput& in, const PyramidOptions& opt) {
    check_input(mesh, in, opt);
    PyramidResult result;
    result.stats.fronts = static_cast<index_t>(in.front_quads.size() / 4);
    result.first_apex = mesh.point_count();
    result.first_pyramid = mesh.cell_count(CellKind::Pyramid);
    if (result.stats.fronts == 0) return result;

    std::unique_ptr<IdealApexes> apexes;
    const std::vector<Front> fronts = make_fronts(mesh, in.front_quads, in.boundary_triangles, opt, &apexes, in.front_scale);
    const Adjacency neighbours = front_neighbours(fronts, apexes.get());
    apexes.reset();
    const std::vector<Box> boxes = fixed_face_boxes(mesh, in);
    const FaceTree face_tree(boxes);
    FrontState state(mesh, fronts, in.boundary_triangles);
    const World world{fronts, neighbours, face_tree, static_cast<index_t>(in.boundary_triangles.size() / 3),
                      in.obstacle_quads, state};

    AdvancingFront advance(world, state, opt, result.stats, in.sweep_size);
    advance.run();
    result.stats.verdicts = advance.tally().verdicts;
    if (result.stats.batches > 0) result.stats.batch_mean /= result.stats.batches;

    append_to_mesh(mesh, fronts, state, in.boundary_triangles.size() / 3, in.region, result);
    return result;
}

}  // namespace tubemesh
