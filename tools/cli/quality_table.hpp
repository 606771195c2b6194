#pragma once
// Quality report laid out like the paper's Table 1: per kind the count, then min and mean of
// each measure (and max, which the paper omits), then the 10-class histograms of Fig. 7.
#include <nlohmann/json.hpp>
#include <string>

#include "engine/quality/quality.hpp"

namespace tubemesh::cli {

std::string format_quality_table(const QualitySummary& q, index_t nodes);

// The time of the phase that made each kind (tets: "tets", pyramids: "pyramids", hexes:
// "sweep"); negative when that phase did not run.
struct KindTimes {
    double tet = -1, pyramid = -1, hex = -1;
};

// Table 1 of a meshing run: as above with a "Wall time" row per kind (the paper's row says CPU
// time; a parallel run is measured by the clock on the wall), then the total time and
// elements per second (all cells over the total).
std::string format_run_table(const QualitySummary& q, index_t nodes, const KindTimes& times, double total_seconds);
nlohmann::json quality_json(const QualitySummary& q);

}  // namespace tubemesh::cli
