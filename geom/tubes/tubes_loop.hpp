#pragma once
// A tube's end loop (one or several B-rep edges) as one closed curve parametrised by arc
// length: where ring nodes go, and where a generator line of the wall meets the loop.
#include <BRepAdaptor_Curve.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Pnt.hxx>

#include <optional>
#include <vector>

#include "geom/model/model.hpp"
#include "geom/tubes/tubes_topology.hpp"

namespace tubemesh::geom {

struct LoopPoint {
    int item = 0;  // which edge of the loop (index in loop order)
    double t = 0;  // parameter on that edge's curve
    double s = 0;  // arc length from the loop's start, in [0, length)
    gp_Pnt p;
};

class LoopCurve {
public:
    LoopCurve(const Model& model, const HoleLoop& loop);

    double length() const { return length_; }
    int edge_count() const { return static_cast<int>(items_.size()); }
    int edge_id(int item) const { return items_[item].id; }

    // The point at arc length s from the loop's start, s taken modulo length().
    LoopPoint at(double s) const;
    // The loop point at parameter t of B-rep edge `edge`; nullopt when the edge is not in it.
    std::optional<LoopPoint> locate(int edge, double t) const;

private:
    struct Item {
        int id;
        bool forward;  // the loop runs along the edge's parameter
        Handle(BRepAdaptor_Curve) curve;
        double t0, t1;  // the edge's parameter range
        double s0;      // arc length at the item's start (in loop direction)
        double length;
    };
    double param_at(const Item& item, double ds) const;

    std::vector<Item> items_;
    double length_ = 0;
};

}  // namespace tubemesh::geom
