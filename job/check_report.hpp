#pragma once
// The report of `tubemesh check` (and the Python module's check()): counts, validity,
// conformity, volume, groups and Table 1 of a mesh, as one JSON object.
#include <nlohmann/json.hpp>

#include "engine/check/mesh_check.hpp"
#include "engine/quality/quality.hpp"

namespace tubemesh::job {

nlohmann::json check_json(const HybridMesh& mesh, const CheckReport& report, const QualitySummary& q);

}  // namespace tubemesh::job
