// The local ring closer to the face (heavy: the global ring's runs these are compared with take
// tens of seconds).
#include <gtest/gtest.h>

#include <string>

#include "engine/core/types.hpp"
#include "geom/builders/spec_json.hpp"
#include "geom/mesh_file.hpp"

namespace tubemesh {
namespace {

MeshOptions local_ring() {
    MeshOptions o;
    o.local_ring = true;
    return o;
}

TEST(LocalRingHeavy, HalfARadiusFromTheFloorMeshes) {
    const geom::BlockSpec spec = geom::parse_block_spec(R"({"box": [4, 3, 2], "check_clearance": false, "pipes": [
        {"path": "line", "diameter": 0.1, "points": [[0, 1.5, 0.075], [4, 1.5, 0.075]]}]})",
                                                        "pipe above the floor");
    const geom::MeshRun run = geom::mesh_spec(spec, local_ring());
    EXPECT_TRUE(run.result.check.violations.empty());
    const std::size_t elements = run.result.mesh.cell_count(CellKind::Hex) +
                                 run.result.mesh.cell_count(CellKind::Pyramid) +
                                 run.result.mesh.cell_count(CellKind::Tet);
    EXPECT_LT(elements, std::size_t{2 * 19836});  // the global ring: 206,123
}

}  // namespace
}  // namespace tubemesh
