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

std::string counts_of(const HybridMesh& mesh) {
    return number(element_count(mesh), "%.0f") + " elements (" + number(mesh.cell_count(CellKind::Hex), "%.0f") +
           " hexes, " + number(mesh.cell_count(CellKind::Pyramid), "%.0f") + " pyramids, " +
           number(mesh.cell_count(CellKind::Tet), "%.0f") + " tets, " +
           number(double(mesh.face_count(FaceKind::Tri)) + mesh.face_count(FaceKind::Quad), "%.0f") +
           " boundary faces)";
}

// `needed`: the run's whole count when it is known, else what it is known to pass.
std::string advice(double needed, bool known, const ElementCap& cap) {
    const double estimate = cap.tets + cap.triangles + cap.hexes + cap.pyramids + cap.quads;
    return (known ? "give --max-elements " + number(rounded_up(needed)) + " or more"
                  : "the run needs at least " + number(needed) + ": give a larger --max-elements") +
           ", or larger sizes (--size, or --sweep-size where the sizing rules accept it); the estimate before "
           "meshing was " + number(estimate) + ", a lower bound the real counts exceed";
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

void check_refining_tets(const HybridMesh& mesh, double tets, const ElementCap& cap) {
    if (!std::isfinite(cap.limit)) return;
    const double made = element_count(mesh), kept = kRefinedTetsKept * tets;
    if (made + kept <= cap.limit) return;
    throw Error("while refining the tets: the mesh has " + counts_of(mesh) + " and the tet step holds " +
                number(tets, "%.0f") + " tets, of which it keeps at least " + number(kept) + ", " +
                number(made + kept) + " in all: more than " + cap.limit_text + "; stopped before meshing further: " +
                advice(made + kept, false, cap));
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

    const std::string counts = counts_of(mesh);
    const std::string help = advice(made + to_come, reached == until, cap);
    if (reached == until)
        throw Error("the mesh has " + counts + ", more than " + cap.limit_text + "; no file is written: " + help);
    throw Error(std::string("after the ") + stage_name(reached) + " stage the mesh has " + counts +
                " and the stages left add at least " + number(to_come) + " more, " + number(made + to_come) +
                " in all: more than " + cap.limit_text + "; stopped before meshing further: " + help);
}

}  // namespace tubemesh
