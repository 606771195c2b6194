// `tubemesh check MESH [--json]`: counts, validity, conformity and the quality table.
// Exit 0 when valid and conforming, 1 when not, 2 when the file cannot be read.
#include <fmt/format.h>

#include <memory>

#include "engine/check/mesh_check.hpp"
#include "engine/io/mesh_io.hpp"
#include "engine/quality/quality.hpp"
#include "tools/cli/commands.hpp"
#include "job/check_report.hpp"
#include "job/quality_table.hpp"

namespace tubemesh::cli {

namespace {

struct CheckArgs {
    std::string path;
    bool json = false;
};

void print_text(const std::string& path, const HybridMesh& mesh, const CheckReport& report, const QualitySummary& q) {
    fmt::print("{}: {} nodes, {} hexahedra, {} pyramids, {} tetrahedra; {} boundary triangles, {} boundary quads\n",
               path, mesh.point_count(), mesh.cell_count(CellKind::Hex), mesh.cell_count(CellKind::Pyramid),
               mesh.cell_count(CellKind::Tet), mesh.face_count(FaceKind::Tri), mesh.face_count(FaceKind::Quad));
    fmt::print("volume {:.9g}, boundary area {:.9g}, {} interior faces, {} free faces\n", report.volume,
               report.boundary_area, report.interior_faces, report.boundary_faces);
    if (report.ok())
        fmt::print("valid and conforming\n\n");
    else
        fmt::print("NOT valid or not conforming:\n{}\n", describe(report));
    fmt::print("{}", job::format_quality_table(q, mesh.point_count()));
}

}  // namespace

Command add_check_command(CLI::App& app) {
    auto args = std::make_shared<CheckArgs>();
    CLI::App* cmd = app.add_subcommand("check", "Check a mesh file: validity, conformity, quality (Table 1 layout)");
    cmd->add_option("MESH", args->path, "Mesh file (Gmsh MSH 4.1, ASCII or binary)")->required();
    cmd->add_flag("--json", args->json, "Print the report as one JSON object");
    cmd->footer("Exit status: 0 valid and conforming, 1 violations found, 2 file cannot be read.");
    return {cmd, [args]() -> int {
        const HybridMesh mesh = read_msh(args->path);  // Error -> exit 2 in main
        const CheckReport report = check_mesh(mesh);
        const QualitySummary quality = summarize_quality(mesh);
        if (args->json)
            fmt::print("{}\n", job::check_json(mesh, report, quality).dump(2));
        else
            print_text(args->path, mesh, report, quality);
        return report.ok() ? 0 : 1;
    }};
}

}  // namespace tubemesh::cli
