#include "geom/tubes/ring_coverage.hpp"

#include <fmt/format.h>

namespace tubemesh::geom {

double ring_share(const std::vector<RingCoverage>& pipes) {
    double wall = 0, ring = 0;
    for (const RingCoverage& p : pipes) {
        wall += p.wall_area;
        ring += p.share * p.wall_area;
    }
    return wall > 0 ? ring / wall : 1.0;
}

std::vector<std::string> coverage_lines(const std::vector<RingCoverage>& pipes) {
    std::vector<std::string> lines;
    if (pipes.empty()) return lines;
    for (const RingCoverage& p : pipes) {
        std::string faces;
        for (int f : p.faces) faces += fmt::format("{}{}", faces.empty() ? "" : ",", f);
        const std::string name = p.tube > 0 ? fmt::format("pipe {} (faces {})", p.tube, faces) : fmt::format("faces {}", faces);
        std::string line =
            p.tube > 0 ? fmt::format("  {}: {:.0f}% of wall area {:.4g} under a hex ring {:.4g} to {:.4g} thick", name,
                                     100 * p.share, p.wall_area, p.thinnest, p.thickest)
                       : fmt::format("  {}: no hex ring on wall area {:.4g}", name, p.wall_area);
        if (p.length > 0) line += fmt::format(" (the ring stops {:.4g} along its length {:.4g})", p.ring_length, p.length);
        if (!p.reason.empty()) line += ": " + p.reason;
        lines.push_back(std::move(line));
    }
    lines.insert(lines.begin(), fmt::format("hex rings cover {:.1f}% of the pipes' wall area", 100 * ring_share(pipes)));
    return lines;
}

}  // namespace tubemesh::geom
