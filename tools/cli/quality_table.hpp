#pragma once
// Quality report laid out like the paper's Table 1: per kind the count, then min and mean of
// each measure (and max, which the paper omits), then the 10-class histograms of Fig. 7.
#include <nlohmann/json.hpp>
#include <string>

#include "engine/quality/quality.hpp"

namespace tubemesh::cli {

std::string format_quality_table(const QualitySummary& q, index_t nodes);
nlohmann::json quality_json(const QualitySummary& q);

}  // namespace tubemesh::cli
