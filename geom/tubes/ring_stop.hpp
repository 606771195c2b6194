#pragma once
// Rings that stop on a cross-section inside the solid (TubeData::stops), geom's side: the pipe
// wall split by the circle where the ring stops, so the wall beyond is a face of its own with a
// real edge there, and the ring's TubeData cut back to the stretch of wall it covers. Where to
// stop (walls that meet, a close spot) is the caller's choice.
//
// No OpenCASCADE header here.
#include "engine/geometry/tube_data.hpp"
#include "geom/model/model.hpp"
#include "geom/tubes/tubes.hpp"

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

// The wall face of `faces` the cross-section through `centre` (on the tube's axis) cuts: the one
// nearest `centre`.
int wall_face_at(const Model& model, const std::vector<int>& faces, const Vec3& centre);

// The closed edge two of `faces` share (no seam) whose centre lies nearest `centre`, within
// `reach`: where split_wall cut the wall; 0 when there is none.
int stop_edge_at(const Model& model, const std::vector<int>& faces, const Vec3& centre, double reach);

// `tube`, found on a model whose wall `edge` splits, cut back to the stretch from its end nearer
// `keep` to `edge` (TubeInfo::stop; that end becomes E1). Throws tubemesh::Error when `edge` does
// not split the wall between its ends.
TubeInfo stopped_tube(const Model& model, const TubeInfo& tube, int edge, const Vec3& keep);

// The whole tube of a stopped one, its ring's end first: what discretize follows the wall on.
TubeInfo whole_tube(const TubeInfo& stopped);

// Points along the edges `edges`, at 17 evenly spaced parameters each: where a loop lies.
std::vector<Vec3> edge_points(const Model& model, const std::vector<int>& edges);

// Per face id of `from` (element id - 1), the id of the same face in `to`; 0 where `to` has it
// no more (a face split_wall cut).
std::vector<int> same_faces_in(const Model& from, const Model& to);

}  // namespace tubemesh::geom
