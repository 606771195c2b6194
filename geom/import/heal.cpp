#include "geom/import/heal.hpp"

#include <Message_ListOfMsg.hxx>
#include <ShapeExtend_DataMapIteratorOfDataMapOfShapeListOfMsg.hxx>
#include <ShapeExtend_MsgRegistrator.hxx>
#include <ShapeAnalysis_ShapeTolerance.hxx>
#include <ShapeFix_Shape.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <cstdio>
#include <map>
#include <tuple>

#include "geom/import/occt_messages.hpp"

namespace tubemesh::geom {

namespace {

struct ShapeSummary {
    int faces = 0, edges = 0, vertices = 0;
    double max_tolerance = 0;
};

ShapeSummary summarize(const TopoDS_Shape& shape) {
    ShapeSummary s;
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(shape, TopAbs_FACE, map);
    s.faces = map.Extent();
    map.Clear();
    TopExp::MapShapes(shape, TopAbs_EDGE, map);
    s.edges = map.Extent();
    map.Clear();
    TopExp::MapShapes(shape, TopAbs_VERTEX, map);
    s.vertices = map.Extent();
    s.max_tolerance = ShapeAnalysis_ShapeTolerance().Tolerance(shape, 1);  // 1: the maximum
    return s;
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

}  // namespace

std::optional<TopoDS_Shape> heal_shape(const TopoDS_Shape& shape, std::vector<std::string>& changes) {
    load_healing_messages();  // before the fixer creates its messages
    Handle(ShapeExtend_MsgRegistrator) registrator = new ShapeExtend_MsgRegistrator;
    Handle(ShapeFix_Shape) fixer = new ShapeFix_Shape(shape);
    fixer->SetMsgRegistrator(registrator);
    try {
        fixer->Perform();
    } catch (const Standard_Failure& e) {
        changes.push_back(std::string("healing failed (OpenCASCADE: ") + e.GetMessageString() + "); the solid is used as read");
        return std::nullopt;
    }

    // The registrator keys messages by sub-shape in a hash map: count identical texts so the
    // report does not depend on the map's order and does not repeat one fix per edge.
    std::map<std::string, int> counts;
    for (ShapeExtend_DataMapIteratorOfDataMapOfShapeListOfMsg it(registrator->MapShape()); it.More(); it.Next())
        for (Message_ListOfMsg::Iterator msg(it.Value()); msg.More(); msg.Next())
            ++counts[healing_message_text(msg.Value())];
    for (const auto& [text, count] : counts)
        changes.push_back(count > 1 ? text + " (x" + std::to_string(count) + ")" : text);

    // ShapeFix flags itself "done" on clean shapes too (it re-runs SameParameter), so its status
    // says little. What a user cares about: did the topology or the tolerances change?
    const TopoDS_Shape healed = fixer->Shape();
    const ShapeSummary before = summarize(shape), after = summarize(healed);
    for (const auto& [name, a, b] : {std::tuple{"faces", before.faces, after.faces},
                                     std::tuple{"edges", before.edges, after.edges},
                                     std::tuple{"vertices", before.vertices, after.vertices}})
        if (a != b) changes.push_back(std::string(name) + ": " + std::to_string(a) + " -> " + std::to_string(b));
    if (after.max_tolerance > 1.01 * before.max_tolerance)
        changes.push_back("largest tolerance grew from " + number(before.max_tolerance) + " to " +
                          number(after.max_tolerance));
    return healed;
}

}  // namespace tubemesh::geom
