#include "tests/support/tets_pipeline_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "engine/mesh/topology.hpp"
#include "engine/core/vec3_ops.hpp"
#include "engine/predicates/predicates.hpp"
#include "engine/quality/quality.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/prepare.hpp"

namespace tubemesh::tets_acceptance {

namespace {

using Key = std::array<index_t, 3>;

// One face of one tet, named by its sorted nodes; `apex` is the tet's fourth node.
struct FaceRecord {
    Key key;
    index_t tet;
    index_t apex;
    bool operator<(const FaceRecord& o) const { return key != o.key ? key < o.key : tet < o.tet; }
};

Key sorted(index_t a, index_t b, index_t c) {
    Key k{a, b, c};
    std::sort(k.begin(), k.end());
    return k;
}

// The front triangles' keys, sorted for binary search.
std::vector<Key> front_keys(const PipelineResult& r) {
    std::vector<Key> keys;
    keys.reserve(r.tet_front.size() / 3);
    for (std::size_t i = 0; i + 2 < r.tet_front.size(); i += 3)
        keys.push_back(sorted(r.tet_front[i], r.tet_front[i + 1], r.tet_front[i + 2]));
    std::sort(keys.begin(), keys.end());
    return keys;
}

const double* coords(const HybridMesh& m, index_t v, std::array<double, 3>& out) {
    out = {m.x[v], m.y[v], m.z[v]};
    return out.data();
}

double signed_volume(const HybridMesh& m, index_t a, index_t b, index_t c, index_t d) {
    return tet_volume(m.point(a), m.point(b), m.point(c), m.point(d));
}

void note(std::string& problems, int& noted, const std::string& line) {
    if (noted++ < 8) problems += line + "\n";
}

void measure_faces(const PipelineResult& r, TetFigures& f) {
    const HybridMesh& m = r.mesh;
    const index_t tets = m.cell_count(CellKind::Tet);
    std::vector<FaceRecord> faces;
    faces.reserve(4 * std::size_t{tets});
    for (index_t t = 0; t < tets; ++t) {
        const auto v = m.cell(CellKind::Tet, t);
        for (int k = 0; k < 4; ++k) {
            const auto& n = kTetTopology.face[k].node;
            faces.push_back({sorted(v[n[0]], v[n[1]], v[n[2]]), t, v[k]});
        }
    }
    std::sort(faces.begin(), faces.end());
    const std::vector<Key> front_sorted = front_keys(r);

    int noted = 0;
    const auto by_key = [](const FaceRecord& a, const Key& k) { return a.key < k; };
    std::array<double, 3> pa, pb, pc, pd;
    for (std::size_t i = 0; i < r.tet_front.size() / 3; ++i) {
        const index_t a = r.tet_front[3 * i], b = r.tet_front[3 * i + 1], c = r.tet_front[3 * i + 2];
        const Key key = sorted(a, b, c);
        const auto lo = std::lower_bound(faces.begin(), faces.end(), key, by_key);
        auto hi = lo;
        while (hi != faces.end() && hi->key == key) ++hi;
        if (hi - lo != 1) {
            ++f.front_not_one_tet;
            note(f.first_problems, noted,
                 "front triangle " + std::to_string(i) + " is a face of " + std::to_string(hi - lo) + " tets");
            continue;
        }
        // The normal points out of the region: the tet's apex must lie behind it.
        if (predicates::orient3d(coords(m, a, pa), coords(m, b, pb), coords(m, c, pc), coords(m, lo->apex, pd)) >= 0) {
            ++f.front_wrong_side;
            note(f.first_problems, noted,
                 "front triangle " + std::to_string(i) + ": tet " + std::to_string(lo->tet) + " is on its outer side");
        }
    }
    for (std::size_t i = 0; i < faces.size();) {
        std::size_t j = i;
        while (j < faces.size() && faces[j].key == faces[i].key) ++j;
        const bool is_front = std::binary_search(front_sorted.begin(), front_sorted.end(), faces[i].key);
        if (j - i > 2) {
            ++f.crowded_faces;
            note(f.first_problems, noted, "a face of tet " + std::to_string(faces[i].tet) + " is on " +
                                              std::to_string(j - i) + " tets");
        } else if (j - i == 1 && !is_front) {
            ++f.loose_faces;
            note(f.first_problems, noted,
                 "a face of tet " + std::to_string(faces[i].tet) + " is on no other tet and not on the front");
        }
        i = j;
    }
}

void measure_tets_themselves(const PipelineResult& r, TetFigures& f) {
    const HybridMesh& m = r.mesh;
    int noted = 0;
    std::array<double, 3> p[4];
    for (index_t t = 0; t < m.cell_count(CellKind::Tet); ++t) {
        const auto v = m.cell(CellKind::Tet, t);
        if (predicates::orient3d(coords(m, v[0], p[0]), coords(m, v[1], p[1]), coords(m, v[2], p[2]),
                                 coords(m, v[3], p[3])) <= 0) {
            ++f.not_positive;
            note(f.first_problems, noted, "tet " + std::to_string(t) + " is not positively oriented");
        }
        f.tet_volume += signed_volume(m, v[0], v[1], v[2], v[3]);
    }
    // The front's enclosed volume: cones from one point over its triangles (outward normals).
    if (!r.tet_front.empty()) {
        const index_t o = r.tet_front[0];
        for (std::size_t i = 0; i + 2 < r.tet_front.size(); i += 3)
            f.enclosed_volume += signed_volume(m, o, r.tet_front[i], r.tet_front[i + 1], r.tet_front[i + 2]);
    }
    const std::vector<double> q = cell_quality(m, CellKind::Tet);
    if (!q.empty()) {
        f.min_collapse = std::numeric_limits<double>::infinity();
        double sum = 0;
        for (double x : q) {
            f.min_collapse = std::min(f.min_collapse, x);
            sum += x;
            f.below_0_2 += x < 0.2;
            f.below_0_3 += x < 0.3;
        }
        f.mean_collapse = sum / static_cast<double>(q.size());
        const index_t worst = static_cast<index_t>(std::min_element(q.begin(), q.end()) - q.begin());
        std::vector<char> on_front(m.point_count(), 0);
        for (index_t v : r.tet_front) on_front[v] = 1;
        const std::vector<Key> front = front_keys(r);
        const auto v = m.cell(CellKind::Tet, worst);
        for (int k = 0; k < 4; ++k) {
            f.worst_front_nodes += on_front[v[k]];
            const auto& n = kTetTopology.face[k].node;
            f.worst_front_faces += std::binary_search(front.begin(), front.end(), sorted(v[n[0]], v[n[1]], v[n[2]]));
        }
    }
}

}  // namespace

TetFigures measure_tets(const std::string& name, const PipelineResult& r) {
    TetFigures f;
    f.name = name;
    f.front_triangles = static_cast<index_t>(r.tet_front.size() / 3);
    f.tets = r.mesh.cell_count(CellKind::Tet);
    f.stats = r.tet_stats;
    f.new_points = r.tet_stats.new_points;
    f.pipeline_seconds = r.seconds;
    measure_faces(r, f);
    measure_tets_themselves(r, f);
    f.check = check_mesh(r.mesh);
    return f;
}

TetFigures measure_tets(const std::string& name, const geom::BlockSpec& spec, const MeshOptions& options) {
    const geom::BuiltBlock block = geom::build_block(spec);
    const geom::PreparedModel prepared = geom::prepare_model(block.model, geom::prepare_options(options));
    const PipelineResult r = run_pipeline(prepared.pipeline_input(), options, Stage::Tets);
    return measure_tets(name, r);
}

std::string summary(const TetFigures& f) {
    const tets::TetStepStats& s = f.stats;
    std::ostringstream o;
    o << f.name << ": " << f.front_triangles << " front triangles, " << f.tets << " tets, " << f.new_points
      << " new nodes; collapse min " << f.min_collapse << " mean " << f.mean_collapse << ", below 0.2: "
      << f.below_0_2 << ", below 0.3: " << f.below_0_3 << "; the worst has " << f.worst_front_nodes
      << " nodes and " << f.worst_front_faces << " faces on the front\n";
    o << "  before optimisation min " << s.optimise.min_collapse_before << " mean " << s.optimise.mean_collapse_before
      << "; steiner kept " << s.recovery.steiner_kept << ", refinement rounds " << s.refine.rounds << "\n";
    o << "  tet step " << s.seconds << " s (recovery " << s.recovery.seconds_total << ", refinement "
      << s.refine.seconds << ", optimisation " << s.optimise.seconds_total << "), pipeline " << f.pipeline_seconds
      << " s; volume " << f.tet_volume << " vs front " << f.enclosed_volume << "; check "
      << (f.check.ok() ? "ok" : "FAILED") << "\n";
    return o.str();
}

void expect_tets_fill_the_front(const TetFigures& f) {
    SCOPED_TRACE(f.name + " tets");
    EXPECT_GT(f.tets, 0u);
    EXPECT_EQ(f.front_not_one_tet, 0u) << f.first_problems;
    EXPECT_EQ(f.front_wrong_side, 0u) << f.first_problems;
    EXPECT_EQ(f.loose_faces, 0u) << f.first_problems;
    EXPECT_EQ(f.crowded_faces, 0u) << f.first_problems;
    EXPECT_EQ(f.not_positive, 0u) << f.first_problems;
    EXPECT_GT(f.enclosed_volume, 0);
    EXPECT_NEAR(f.tet_volume, f.enclosed_volume, 1e-9 * std::abs(f.enclosed_volume));
    EXPECT_TRUE(f.check.ok()) << describe(f.check);
}

void expect_tet_minimum(const TetFigures& f) {
    SCOPED_TRACE(f.name + " tet quality");
    EXPECT_GE(f.min_collapse, 0.30);
    EXPECT_EQ(f.below_0_2, 0u);
}

void expect_tet_mean(const TetFigures& f) {
    SCOPED_TRACE(f.name + " tet quality");
    EXPECT_GE(f.mean_collapse, 0.80);
}

}  // namespace tubemesh::tets_acceptance
