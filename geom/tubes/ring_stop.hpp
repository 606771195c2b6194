#pragma once
// Rings that stop on a cross-section inside the solid (TubeData::stops), geom's side: the pipe
// wall split by the circle where the ring stops, so the wall beyond is a face of its own with a
// real edge there, and the ring's TubeData cut back to the stretch of wall it covers. Where to
// stop (walls that meet, a close spot) is the caller's choice.
//
// No OpenCASCADE header here.
#include "engine/geometry/tube_data.hpp"
#include "geom/model/model.hpp"

namespace tubemesh::geom {

// The model with wall face `wall` split by the plane through `centre` normal to `axis` (the
// tube's tangent there): the section is one closed edge on the face, and the face becomes two.
// Face and edge ids are those of the new model. Throws tubemesh::Error when the plane does not
// cut the face in one closed edge or the split gives no valid solid.
Model split_wall(const Model& model, int wall, const Vec3& centre, const Vec3& axis);

// Cuts `tube` (discretised on a wall that `edge`, a closed edge between two of its wall faces,
// splits) back to the stretch from its first end to `edge`, where its ring then stops: the wall
// faces beyond leave wall_faces, the face just beyond becomes host2, the edge loop2; the
// stations end on the edge's plane and ring2 holds n nodes on the edge from its vertex by arc
// length, turning as ring1 does. Throws tubemesh::Error when `edge` is not such an edge.
void stop_ring_at_edge(const Model& model, int edge, TubeData& tube);

}  // namespace tubemesh::geom
