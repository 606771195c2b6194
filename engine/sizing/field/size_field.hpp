#pragma once
// Target element size over space, shared by the surface mesher and the tet step.
//
//   h(x) = min(S, min_i (h_i + g·|x - x_i|))
//
// Each point source i (a node of a ring's outer polygon asking for its quad size, or any other
// local size) wants size h_i at x_i; away from it the size may grow by at most g per unit
// distance, up to the overall size S. Two elements that touch lie about one size apart, so
// their target sizes differ by a factor of at most about 1 + g: g = 0.25 leaves room under the
// surface's neighbour ratio of 1.5 for the scatter a mesher adds to any target.
//
// Whatever the sources, |h(x) - h(y)| <= g·|x - y| everywhere, which is what makes h usable
// as the background size of any later step (the tet mesher's interior points included).
#include <memory>
#include <span>
#include <vector>

#include "engine/core/types.hpp"
#include "engine/mesh/hybrid_mesh.hpp"  // Vec3

namespace tubemesh {

class PointIndex;

struct SizeSource {
    Vec3 point;
    double size;
};

struct SizeFieldOptions {
    double max_size = 0;  // S, required (> 0): the size far from every source
    double growth = 0.25;  // g: size increase per unit distance from a source
};

class SizeField {
public:
    // Throws tubemesh::Error for a non-positive S or growth, or a source size that is not
    // positive and finite. Sources larger than S are allowed (they never win).
    SizeField(const SizeFieldOptions& options, std::vector<SizeSource> sources);
    ~SizeField();
    SizeField(const SizeField&) = delete;
    SizeField& operator=(const SizeField&) = delete;

    // h(p). Safe to call from several threads at once.
    double at(const Vec3& p) const;
    // Whether h(p) < limit. Cheaper than at() where the answer is no and the limit small: it
    // looks only at the sources within (limit - min_size) / g. Thread-safe.
    bool below(const Vec3& p, double limit) const;

    double max_size() const { return options_.max_size; }
    double growth() const { return options_.growth; }
    double min_size() const { return min_size_; }  // the smallest size anywhere (min(S, min h_i))
    index_t source_count() const { return static_cast<index_t>(size_.size()); }

private:
    SizeFieldOptions options_;
    std::vector<double> x_, y_, z_, size_;  // the index reads these in place: never resized
    double min_size_ = 0;
    std::unique_ptr<PointIndex> index_;
};

// Sources on a closed polygon (a ring's outer polygon): node k asks for the mean length of its
// two segments. Appends polygon.size() sources to `out`.
void add_polygon_sources(std::span<const Vec3> polygon, std::vector<SizeSource>& out);

}  // namespace tubemesh
