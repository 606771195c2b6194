// Whole runs on many generated blocks (heavy): random blocks 1-1000 and blocks with pipes
// deliberately close to each other and to a face (close_block.hpp, seeds 1-200) mesh and pass
// the check; a pipe no ring fits is meshed with tets (geometry_diagnosis.hpp). A close block whose
// boundary touches itself along a line (a pipe tangent to a face or to the other pipe) has no
// conforming mesh and is refused. Each outcome and the share of pipe wall under hex rings is
// printed for the closing note's counts.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "engine/core/types.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/close_block.hpp"
#include "geom/builders/random_block.hpp"
#include "geom/mesh_file.hpp"

namespace {

using namespace tubemesh;

std::string seed_name(const ::testing::TestParamInfo<int>& info) { return "seed" + std::to_string(info.param); }

void mesh_and_check(const geom::BlockSpec& spec, bool self_contact_allowed) {
    const geom::BuiltBlock block = geom::build_block(spec);
    try {
        const geom::MeshRun run = geom::mesh_model(block.model);
        EXPECT_TRUE(run.result.check.violations.empty()) << spec.name;
        double wall = 0;
        for (const geom::RingCoverage& p : run.coverage) wall += p.wall_area;
        std::printf("%s: meshed, %u tets, worst tet %.3f, pipe wall %.4g, %.3f under rings\n", spec.name.c_str(),
                    static_cast<unsigned>(run.result.mesh.cell_count(CellKind::Tet)),
                    run.result.quality.tet_collapse.min, wall, geom::ring_share(run.coverage));
    } catch (const Error& e) {
        const bool self_contact = std::string(e.what()).find("boundary touches itself") != std::string::npos;
        EXPECT_TRUE(self_contact_allowed && self_contact) << spec.name << ": " << e.what();
        std::printf("%s: %s: %s\n", spec.name.c_str(), self_contact ? "refused" : "FAILED", e.what());
    }
}

class RandomBlocks : public ::testing::TestWithParam<int> {};
TEST_P(RandomBlocks, MeshAndPassTheCheck) {
    mesh_and_check(geom::random_block_spec(static_cast<std::uint64_t>(GetParam())), false);
}
INSTANTIATE_TEST_SUITE_P(Seeds, RandomBlocks, ::testing::Range(1, 1001), seed_name);

class CloseBlocks : public ::testing::TestWithParam<int> {};
TEST_P(CloseBlocks, MeshAndPassTheCheckOrTouchThemselves) {
    const geom::BlockSpec spec = geom::close_block_spec(static_cast<std::uint64_t>(GetParam()));
    try {
        geom::build_block(spec);
    } catch (const Error& e) {
        // OpenCASCADE could not even build it: no solid to mesh, nothing for the mesher to say.
        std::printf("%s: not built: %s\n", spec.name.c_str(), e.what());
        return;
    }
    mesh_and_check(spec, true);
}
INSTANTIATE_TEST_SUITE_P(Seeds, CloseBlocks, ::testing::Range(1, 201), seed_name);

}  // namespace
