#pragma once
// Sum of the signed volumes of a TetDomain's tets (engine/tets/domain/tet_domain.hpp), for the tests
// that check a tet-step phase keeps the region it fills.
#include "engine/core/vec3_ops.hpp"
#include "engine/tets/domain/tet_domain.hpp"
#include "engine/tets/domain/tet_neighbourhood.hpp"

namespace tubemesh::testing {

inline double domain_volume(const tets::TetDomain& d) {
    double v = 0;
    for (index_t t = 0; t < d.tets.size(); ++t) {
        const index_t* q = d.tets.vertex(t);
        v += tet_volume(tets::point_vec(d, q[0]), tets::point_vec(d, q[1]), tets::point_vec(d, q[2]),
                        tets::point_vec(d, q[3]));
    }
    return v;
}

}  // namespace tubemesh::testing
