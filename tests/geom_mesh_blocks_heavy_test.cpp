// Whole runs on many generated blocks (heavy): random blocks 1-500 mesh and pass the check;
// blocks with pipes deliberately close to each other and to a face (close_block.hpp, seeds
// 1-200) mesh and pass the check or end in a geometry diagnosis (geometry_diagnosis.hpp),
// never in another error. Each outcome is printed for the closing note's counts.
#include <gtest/gtest.h>

#include <array>
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

// The run's outcome; an Error that is neither a diagnosis nor a refusal of sizes fails the test.
void mesh_or_diagnose(const geom::BlockSpec& spec, bool diagnosis_allowed) {
    const geom::BuiltBlock block = geom::build_block(spec);
    try {
        const geom::MeshRun run = geom::mesh_model(block.model);
        EXPECT_TRUE(run.result.check.violations.empty()) << spec.name;
        std::printf("%s: meshed, %u tets, worst tet %.3f\n", spec.name.c_str(),
                    static_cast<unsigned>(run.result.mesh.cell_count(CellKind::Tet)),
                    run.result.quality.tet_collapse.min);
    } catch (const Error& e) {
        const std::string m = e.what();
        constexpr std::array<const char*, 5> kDiagnoses = {
            "pipe walls that meet each other", "touches a face tangentially", "a hex ring that fits there",
            "hex rings that fit between them", "the tetrahedra in that gap would be slivers"};
        bool diagnosed = false;
        for (const char* d : kDiagnoses) diagnosed = diagnosed || m.find(d) != std::string::npos;
        EXPECT_TRUE(diagnosis_allowed && diagnosed) << spec.name << ": " << m;
        std::printf("%s: %s: %s\n", spec.name.c_str(), diagnosed ? "diagnosed" : "FAILED", m.c_str());
    }
}

class RandomBlocks : public ::testing::TestWithParam<int> {};
TEST_P(RandomBlocks, MeshAndPassTheCheck) {
    mesh_or_diagnose(geom::random_block_spec(static_cast<std::uint64_t>(GetParam())), false);
}
INSTANTIATE_TEST_SUITE_P(Seeds, RandomBlocks, ::testing::Range(1, 501), seed_name);

class CloseBlocks : public ::testing::TestWithParam<int> {};
TEST_P(CloseBlocks, MeshAndPassTheCheckOrAreDiagnosed) {
    const geom::BlockSpec spec = geom::close_block_spec(static_cast<std::uint64_t>(GetParam()));
    try {
        geom::build_block(spec);
    } catch (const Error& e) {
        // OpenCASCADE could not even build it: no solid to mesh, nothing for the mesher to say.
        std::printf("%s: not built: %s\n", spec.name.c_str(), e.what());
        return;
    }
    mesh_or_diagnose(spec, true);
}
INSTANTIATE_TEST_SUITE_P(Seeds, CloseBlocks, ::testing::Range(1, 201), seed_name);

}  // namespace
