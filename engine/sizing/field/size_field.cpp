#include "engine/sizing/field/size_field.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/mesh/point_index.hpp"
#include "engine/core/vec3_ops.hpp"

namespace tubemesh {

SizeField::SizeField(const SizeFieldOptions& options, std::vector<SizeSource> sources) : options_(options) {
    if (!(options.max_size > 0) || !std::isfinite(options.max_size))
        throw Error("size field: the overall mesh size S must be positive, got " + std::to_string(options.max_size));
    if (!(options.growth > 0) || !std::isfinite(options.growth))
        throw Error("size field: the growth rate must be positive, got " + std::to_string(options.growth));
    min_size_ = options.max_size;
    x_.reserve(sources.size());
    y_.reserve(sources.size());
    z_.reserve(sources.size());
    size_.reserve(sources.size());
    for (const SizeSource& s : sources) {
        if (!(s.size > 0) || !std::isfinite(s.size))
            throw Error("size field: a local size must be positive, got " + std::to_string(s.size) + " at (" +
                        std::to_string(s.point.x) + ", " + std::to_string(s.point.y) + ", " +
                        std::to_string(s.point.z) + ")");
        if (s.size >= options.max_size) continue;  // never below S anywhere: it cannot win
        x_.push_back(s.point.x);
        y_.push_back(s.point.y);
        z_.push_back(s.point.z);
        size_.push_back(s.size);
        min_size_ = std::min(min_size_, s.size);
    }
    if (!size_.empty()) index_ = std::make_unique<PointIndex>(x_, y_, z_);
}

SizeField::~SizeField() = default;

double SizeField::at(const Vec3& p) const {
    const double S = options_.max_size, g = options_.growth;
    if (!index_) return S;
    // The nearest source bounds h(p) from above. Another source j can only do better when
    // h_j + g·d_j < bound, and h_j >= min_size_, so it lies within (bound - min_size_) / g.
    // With one size for all sources that radius is the nearest distance: one k-d query.
    thread_local std::vector<Neighbor> hits;  // per-thread scratch, keeps its capacity
    index_->nearest(p, 1, hits);
    const index_t n = hits.front().index;
    const double dn = std::sqrt(hits.front().distance_squared);
    double best = std::min(S, size_[n] + g * dn);
    const double radius = (best - min_size_) / g;
    if (radius <= dn) return best;
    index_->within(p, radius, hits);
    for (const Neighbor& h : hits) {
        const double d = std::sqrt(h.distance_squared);
        best = std::min(best, size_[h.index] + g * d);
    }
    return best;
}

bool SizeField::below(const Vec3& p, double limit) const {
    if (options_.max_size < limit) return true;
    if (!index_ || !(min_size_ < limit)) return false;
    thread_local std::vector<Neighbor> hits;
    index_->within(p, (limit - min_size_) / options_.growth, hits);
    for (const Neighbor& h : hits)
        if (size_[h.index] + options_.growth * std::sqrt(h.distance_squared) < limit) return true;
    return false;
}

void add_polygon_sources(std::span<const Vec3> polygon, std::vector<SizeSource>& out) {
    const std::size_t n = polygon.size();
    if (n < 3) throw Error("size field: a ring polygon needs at least 3 nodes, got " + std::to_string(n));
    for (std::size_t k = 0; k < n; ++k) {
        const Vec3& prev = polygon[(k + n - 1) % n];
        const Vec3& next = polygon[(k + 1) % n];
        out.push_back({polygon[k], 0.5 * (norm(prev - polygon[k]) + norm(polygon[k] - next))});
    }
}

}  // namespace tubemesh
