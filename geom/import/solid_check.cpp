#include "geom/import/solid_check.hpp"

#include <BRepCheck.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Result.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <set>
#include <sstream>
#include <vector>

namespace tubemesh::geom {

namespace {

std::string status_name(BRepCheck_Status status) {
    std::ostringstream out;
    BRepCheck::Print(status, out);
    std::string s = out.str();
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
}

// Statuses of one sub-shape, on its own and in the context of each shape that holds it (an
// edge is checked once per face it bounds).
std::set<std::string> failures_of(const BRepCheck_Analyzer& analyzer, const TopoDS_Shape& sub) {
    std::set<std::string> out;
    const Handle(BRepCheck_Result)& result = analyzer.Result(sub);
    if (result.IsNull()) return out;
    for (BRepCheck_ListIteratorOfListOfStatus it(result->Status()); it.More(); it.Next())
        if (it.Value() != BRepCheck_NoError) out.insert(status_name(it.Value()));
    for (result->InitContextIterator(); result->MoreShapeInContext(); result->NextShapeInContext())
        for (BRepCheck_ListIteratorOfListOfStatus it(result->StatusOnShape()); it.More(); it.Next())
            if (it.Value() != BRepCheck_NoError) out.insert(status_name(it.Value()));
    return out;
}

}  // namespace

std::string validity_problems(const TopoDS_Shape& shape) {
    BRepCheck_Analyzer analyzer(shape);
    if (analyzer.IsValid()) return {};

    struct Kind {
        TopAbs_ShapeEnum type;
        const char* name;
    };
    // Faces and edges carry the ids users see; the rest are numbered the same way for completeness.
    const Kind kinds[] = {{TopAbs_SOLID, "solid"}, {TopAbs_SHELL, "shell"}, {TopAbs_FACE, "face"},
                          {TopAbs_WIRE, "wire"},   {TopAbs_EDGE, "edge"},   {TopAbs_VERTEX, "vertex"}};
    std::vector<std::string> items;
    for (const Kind& kind : kinds) {
        TopTools_IndexedMapOfShape map;
        TopExp::MapShapes(shape, kind.type, map);
        for (int i = 1; i <= map.Extent(); ++i) {
            const std::set<std::string> failures = failures_of(analyzer, map(i));
            if (failures.empty()) continue;
            std::string item = std::string(kind.name) + "_" + std::to_string(i) + ":";
            for (const std::string& f : failures) item += " " + f;
            items.push_back(item);
        }
    }
    if (items.empty()) return "BRepCheck reports the shape invalid without naming a sub-shape";

    constexpr std::size_t kShown = 3;
    std::string line;
    for (std::size_t i = 0; i < items.size() && i < kShown; ++i) line += (i ? "; " : "") + items[i];
    if (items.size() > kShown) line += " (and " + std::to_string(items.size() - kShown) + " more)";
    return line;
}

}  // namespace tubemesh::geom
