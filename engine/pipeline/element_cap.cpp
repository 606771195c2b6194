#include "engine/pipeline/element_cap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/core/types.hpp"
#include "engine/pipeline/pipeline.hpp"

namespace tubemesh {

namespace {

std::string number(double x, const char* format = "%.3g") {
    char s[32];
    std::snprintf(s, sizeof s, format, x);
    return s;
}

}  // namespace

double rounded_up(double x) {
    if (!(x > 0) || !std::isfinite(x)) return x;
    const double unit = std::pow(10.0, std::floor(std::log10(x)) - 2);
    // The quotient of an exact three-digit figure may land a rounding error above a whole number.
    return std::ceil(x / unit * (1 - 1e-12)) * unit;
}

double element_count(const HybridMesh& mesh) {
    return double(mesh.cell_count()) + double(mesh.face_count(FaceKind::Tri)) + double(mesh.face_count(FaceKind::Quad));
}

void check_element_cap(const HybridMesh& mesh, Stage reached, Stage until, double outer_quads,
                       const ElementCap& cap) {
    if (!std::isfinite(cap.limit)) return;
    const double made = element_count(mesh);
    const double pyramids = std::max(cap.pyramids, outer_quads);
    const auto to_run = [&](Stage s) { return reached < s && s <= until; };
    double to_come = 0;
    if (to_run(Stage::Surface)) to_come += cap.triangles;
    if (to_run(Stage::Pyramids)) to_come += pyramids;
    // The tets beside the rings grow with the pyramids really to be made.
    if (to_run(Stage::Tets)) to_come += cap.tets + cap.tets_per_pyramid * (pyramids - cap.pyramids);
    if (made + to_come <= cap.limit) return;

    const std::string counts =
        number(made, "%.0f") + " elements (" + number(mesh.cell_count(CellKind::Hex), "%.0f") + " hexes, " +
        number(mesh.cell_count(CellKind::Pyramid), "%.0f") + " pyramids, " +
        number(mesh.cell_count(CellKind::Tet), "%.0f") + " tets, " +
        number(double(mesh.face_count(FaceKind::Tri)) + mesh.face_count(FaceKind::Quad), "%.0f") + " boundary faces)";
    const double estimate = cap.tets + cap.triangles + cap.hexes + cap.pyramids + cap.quads;
    const std::string advice = "give --max-elements " + number(rounded_up(made + to_come)) +
                               " or more, or larger sizes (--size, or --sweep-size where the sizing rules accept "
                               "it): the estimate before meshing was " + number(estimate) +
                               ", a lower bound the real counts exceed";
    if (reached == until)
        throw Error("the mesh has " + counts + ", more than " + cap.limit_text + "; no file is written: " + advice);
    throw Error(std::string("after the ") + stage_name(reached) + " stage the mesh has " + counts +
                " and the stages left add at least " + number(to_come) + " more, " + number(made + to_come) +
                " in all: more than " + cap.limit_text + "; stopped before meshing further: " + advice);
}

}  // namespace tubemesh
