// Constrained mode of the kernel (see triangulation.hpp): adopt() and the shrinking of a
// cavity until its point sees every boundary face.
#include "engine/delaunay/triangulation.hpp"

#include <algorithm>
#include <vector>

#include <tbb/parallel_for.h>

#include "engine/delaunay/triangulation_internal.hpp"
#include "engine/predicates/predicates_inline.hpp"

namespace tubemesh::delaunay {
namespace pred = tubemesh::predicates;
using namespace detail;

// ---------------------------------------------------------------------------------------
// Constrained mode: taking over a mesh, and cavities made star-shaped.

void Triangulation::adopt(std::vector<double>&& xyz, TetStore&& tets) {
    if (started()) throw Error("Delaunay: adopt() on a triangulation that already has tets");
    if (xyz.size() % 3 != 0) throw Error("Delaunay: adopt() needs 3 coordinates per point");
    if (tets.size() == 0) throw Error("Delaunay: adopt() needs a mesh with at least one tetrahedron");
    const auto n = static_cast<index_t>(xyz.size() / 3);
    if (n >= kInfiniteVertex) throw Error("Delaunay: too many points for 32-bit ids");
    constrained_ = true;
    xyz_ = std::move(xyz);
    global_.resize(n);
    for (index_t v = 0; v < n; ++v) global_[v] = v;
    local_.assign(n, kNoIndex);
    owner_.assign(n, 0);
    seed_.assign(n, kNoIndex);
    tets_ = std::move(tets);
    hint_ = 0;
    note_memory();
}

// The new tet on boundary face b is the cavity tet with b's far vertex replaced by p: it has a
// positive volume exactly when p sees b from inside the cavity. Shrinking drops the cavity tet
// behind the first face p does not see and keeps what is still connected to `start`; every
// round drops a tet, so it ends.
bool Triangulation::shrink_to_visible(index_t p, index_t start, Scratch& s) {
    const double* pp = point(p);
    const auto sees = [&](const BoundaryFace& b) {
        const double* q[4] = {point(b.v[0]), point(b.v[1]), point(b.v[2]), point(b.v[3])};
        q[b.face] = pp;
        return pred::orient3d_inline(q[0], q[1], q[2], q[3]) > 0;
    };
    for (;;) {
        index_t drop = kNoIndex;
        for (const BoundaryFace& b : s.boundary)
            if (!sees(b)) {
                drop = b.slot;
                break;
            }
        if (drop == kNoIndex) return true;
        if (drop == start) return false;
        s.kept.clear();
        for (index_t c : s.cavity) {
            unmark(tets_.vertex(c));
            if (c != drop) s.kept.push_back(c);
        }
        std::sort(s.kept.begin(), s.kept.end());
        s.cavity.clear();
        s.boundary.clear();
        mark(tets_.vertex(start));
        s.cavity.push_back(start);
        for (std::size_t i = 0; i < s.cavity.size(); ++i) {
            const index_t c = s.cavity[i];
            const index_t* cv = tets_.vertex(c);
            for (unsigned f = 0; f < 4; ++f) {
                const index_t code = tets_.neighbour(4 * c + f);
                if (code != kNoAdjacent) {
                    const index_t n = code >> 2;
                    if (is_marked(tets_.vertex(n))) continue;
                    if (std::binary_search(s.kept.begin(), s.kept.end(), n)) {
                        mark(tets_.vertex(n));
                        s.cavity.push_back(n);
                        continue;
                    }
                }
                s.boundary.push_back({{cv[0] & ~kCavityMark, cv[1], cv[2], cv[3]}, code, f, c});
            }
        }
    }
}

}  // namespace tubemesh::delaunay
