#pragma once
// Tube recognition, geometric half, and the walk both recognition and discretisation use.
//
// A candidate's faces form a tube wall when each face runs around the axis in one parameter
// direction (the closed one, per BRepAdaptor_Surface::IsUClosed/IsVClosed, for a face that
// wraps; the more curved one for a piece of a split wall), none is planar, and the pieces meet
// without a crease along the axis. A generator line is then followed from a point of E1 along
// the axial isoline of each face, across the edges where the wall was split along the axis,
// to E2.
#include <Geom2d_Curve.hxx>
#include <Geom_Surface.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geom/tubes/tubes_generator.hpp"
#include "geom/tubes/tubes_loop.hpp"
#include "geom/tubes/tubes_topology.hpp"

namespace tubemesh::geom {

class TubeWall {
public:
    // The reason build() gives for a group whose faces meet along the axis at an angle starts
    // with this.
    static constexpr std::string_view kCreaseReason = "crease of ";
    // nullptr, with the reason in `why`, when the faces do not form a smooth closed wall.
    static std::unique_ptr<TubeWall> build(const TopologyIndex& index, const TubeCandidate& candidate,
                                           const TubeOptions& options, std::string& why);

    const TubeCandidate& candidate() const { return candidate_; }
    const LoopCurve& loop(int k) const { return *loops_[k]; }

    // The generator line through E1's point `start`, or nullopt when it cannot be followed to E2.
    std::optional<Generator> walk(const LoopPoint& start) const;

private:
    // An edge a generator line can cross: an end-loop edge, or an edge across which the wall
    // was split along the axis. Seams and splits around the axis run along generator lines and
    // are never crossed.
    struct Cut {
        int edge;
        int loop;  // 0: E1, 1: E2, -1: inside the wall
        TopoDS_Edge shape;
        Handle(Geom2d_Curve) pcurve;
        double t0, t1;  // the uv curve's range
        double e0, e1;  // the edge's (3D curve's) range
        // Edges are not always "same range": ShapeUpgrade_ShapeDivideClosed leaves periodic
        // circles whose uv curve runs one period away from the 3D curve. Parameters are mapped
        // linearly between the two ranges; everything outside a Cut uses the edge's own.
        double to_uv_param(double t) const { return t0 + (t - e0) * (t1 - t0) / (e1 - e0); }
        double to_edge_param(double t) const { return e0 + (t - t0) * (e1 - e0) / (t1 - t0); }
    };
    struct Face {
        int id;
        TopoDS_Face shape;
        Handle(Geom_Surface) surface;
        int circ;           // 0: u runs around the axis, 1: v
        double period;      // > 0 when the face wraps around: its circumferential span
        double c_lo, c_hi;  // circumferential parameter range
        std::vector<Cut> cuts;
    };
    struct Crossing {
        double axial;  // axial parameter on the face
        int edge;
        int loop;
        double t;  // parameter on the edge (its own range)
        gp_Pnt p;
    };
    struct Entry {
        int face;  // index into faces_
        double c;  // circumferential parameter there
        gp_Pnt p;
    };

    TubeWall(const TopologyIndex& index, TubeCandidate candidate);
    std::string classify_faces(const TubeOptions& options);
    std::string find_cuts(Face& f, const TubeOptions& options);
    std::string check_crease(const Face& f, const TopoDS_Edge& edge, int id, const gp_Pnt2d& uv,
                             const TubeOptions& options) const;
    std::vector<Crossing> crossings(const Face& face, double c) const;
    std::optional<Entry> enter(int edge, double t, int from_face) const;
    int face_index(int id) const;

    const TopologyIndex& index_;
    TubeCandidate candidate_;
    std::array<std::unique_ptr<LoopCurve>, 2> loops_;
    std::vector<Face> faces_;
    double tolerance_ = 0;  // distance below which two crossings are the same point
};

}  // namespace tubemesh::geom
