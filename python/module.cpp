// The Python module `tubemesh`: mesh(), check(), make_block(), presets() and the Mesh result
// (mesh_result.hpp). Options, defaults, messages and reports are the CLI's own
// (job/), so `tubemesh.mesh(...)` and `tubemesh mesh ...` take the same values and
// refuse the same ones. Errors raise tubemesh.Error (a RuntimeError) with the CLI's one-line
// message; the GIL is released while meshing and checking; Ctrl-C stops a run (interrupt.hpp).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "engine/check/mesh_check.hpp"
#include "engine/io/mesh_io.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/make_block.hpp"
#include "geom/builders/presets.hpp"
#include "python/interrupt.hpp"
#include "python/mesh_result.hpp"
#include "job/check_report.hpp"
#include "job/mesh_settings.hpp"

namespace py = pybind11;

namespace tubemesh::python {

namespace {

std::string path_text(const py::object& path) { return py::str(py::module_::import("os").attr("fspath")(path)); }

bool is_preset(const std::string& name) {
    for (const geom::PresetInfo& p : geom::preset_list())
        if (p.name == name) return true;
    return false;
}

py::object json_object(const nlohmann::json& j) { return py::module_::import("json").attr("loads")(j.dump()); }

std::unique_ptr<MeshResult> mesh(const py::object& source, bool economy, std::optional<double> size,
                                 std::optional<double> sweep_size, std::optional<int> circ, std::optional<int> layers,
                                 std::optional<double> axial_aspect, std::optional<double> chordal, double pyramid_height,
                                 double gradation, std::optional<int> threads, int tet_parts, int tet_relax,
                                 bool move_apexes, bool slide_surface, bool local_ring, std::optional<double> max_elements,
                                 std::optional<int> solid,
                                 const std::string& until,
                                 const py::object& progress) {
    job::MeshSettings s;
    s.size = size;
    s.sweep_size = sweep_size;
    s.circumferential = circ;
    if (layers) s.layers = *layers;
    if (axial_aspect) s.axial_aspect = *axial_aspect;
    if (chordal) s.chordal = *chordal;
    s.chordal_given = chordal.has_value();
    if (economy) job::apply_economy(s, {layers.has_value(), axial_aspect.has_value(), chordal.has_value()});
    s.pyramid_height = pyramid_height;
    s.gradation = gradation;
    s.threads = threads;
    s.tet_parts = tet_parts;
    s.tet_relax = tet_relax;
    s.move_apexes = move_apexes;
    s.slide_surface = slide_surface;
    s.local_ring = local_ring;
    s.max_elements = max_elements;
    s.solid = solid;
    s.until = job::stage_named(until, job::Naming::Keywords);
    MeshOptions options = job::mesh_options(s, job::Naming::Keywords);
    const std::string name = path_text(source);
    const bool preset = is_preset(name) && !std::filesystem::exists(name);

    InterruptListener listener(progress);
    options.progress = listener.callback();
    auto result = std::make_unique<MeshResult>();
    bool interrupted = false;
    {
        py::gil_scoped_release release;
        try {
            result->run = preset ? geom::mesh_preset(name, options, s.until)
                                 : geom::mesh_file(name, options,
                                                   {.solid = s.solid.value_or(0), .until = s.until, .keyword_names = true});
        } catch (const Interrupted&) {
            interrupted = true;
        }
    }
    if (interrupted) listener.raise_kept_error();
    return result;
}

py::object check(const py::object& path) {
    const std::string p = path_text(path);
    nlohmann::json report;
    {
        py::gil_scoped_release release;
        const HybridMesh mesh = read_msh(p);
        report = job::check_json(mesh, check_mesh(mesh), summarize_quality(mesh));
    }
    return json_object(report);
}

py::object make_block(const py::object& out, const std::string& preset, std::optional<std::uint64_t> seed,
                      const std::optional<py::object>& spec) {
    geom::MakeBlockArgs args;
    args.preset = preset;
    args.seed = seed;
    if (spec) args.spec = path_text(*spec);
    const std::string path = path_text(out);
    geom::BlockInfo info;
    {
        py::gil_scoped_release release;
        info = geom::make_block(args, path);
    }
    py::dict d;
    d["name"] = info.name;
    d["length_unit"] = info.length_unit;
    d["pipe_count"] = info.pipe_count;
    d["pipe_diameters"] = info.pipe_diameters;
    d["volume"] = info.volume;
    d["expected_volume"] = info.expected_volume ? py::object(py::float_(*info.expected_volume)) : py::none();
    d["path"] = path;
    return d;
}

}  // namespace

}  // namespace tubemesh::python

PYBIND11_MODULE(tubemesh, m) {
    using namespace tubemesh;
    namespace tp = tubemesh::python;
    m.doc() = "tubemesh: conforming hybrid meshes (hex rings, pyramids, tets) for solids with tubular holes";
    m.attr("__version__") = TUBEMESH_VERSION;
    py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
    tp::bind_mesh_result(m);

    const job::MeshSettings d;  // the CLI's defaults
    m.def("mesh", &tp::mesh, py::arg("source") = "paper-ex1", py::kw_only(), py::arg("economy") = false,
          py::arg("size") = py::none(), py::arg("sweep_size") = py::none(), py::arg("circ") = py::none(),
          py::arg("layers") = py::none(), py::arg("axial_aspect") = py::none(), py::arg("chordal") = py::none(),
          py::arg("pyramid_height") = d.pyramid_height,
          py::arg("gradation") = d.gradation, py::arg("threads") = py::none(), py::arg("tet_parts") = d.tet_parts,
          py::arg("tet_relax") = d.tet_relax, py::arg("move_apexes") = d.move_apexes,
          py::arg("slide_surface") = d.slide_surface, py::arg("local_ring") = d.local_ring,
          py::arg("max_elements") = py::none(), py::arg("solid") = py::none(),
          py::arg("until") = std::string(stage_name(d.until)), py::arg("progress") = py::none(),
          R"doc(Meshes a CAD file (.step .stp .iges .igs .brep) or a built-in block (a preset name, see presets()).

The options and defaults are `tubemesh mesh`'s (README, "Command line"); None is automatic:
size (S: bounding-box diagonal / 25, at least 1.3 St), sweep_size (St: the smallest tube
diameter, cut by the paper's rules), circ (n: the multiple of 4 nearest 2 pi (r + St/2) / St, at
least 8), layers (2), axial_aspect (1.5), chordal (0.008125), threads (all cores), max_elements
(what the memory this process may use holds; the real counts are capped too), solid (the file's only solid); slide_surface=False is
--fixed-surface; local_ring=False is --global-ring. economy=True is --economy: the
paper's ring (circ 4, layers 2, axial_aspect 2, chordal 0.02, St a share of S) where those are None. until: the last stage ('sweep', 'surface', 'pyramids', 'tets'). progress: a callable
(phase, done, total), called with the GIL from the meshing threads.

Returns a tubemesh.Mesh. Raises tubemesh.Error with the CLI's one-line message; the GIL is
released while meshing; Ctrl-C (KeyboardInterrupt) stops the run within a phase's next progress
step.)doc");
    m.def("check", &tp::check, py::arg("path"),
          "Checks a Gmsh .msh file (as `tubemesh check --json`): counts, validity, conformity, volume, groups, "
          "quality. Returns the report as a dict; raises tubemesh.Error when the file cannot be read.");
    m.def("make_block", &tp::make_block, py::arg("out"), py::kw_only(), py::arg("preset") = "",
          py::arg("seed") = py::none(), py::arg("spec") = py::none(),
          "Builds a block (a preset, a random seed or a JSON spec: exactly one) and writes it as STEP to `out` (as "
          "`tubemesh make-block`). Returns what was built: name, length_unit, pipe_count, pipe_diameters, volume, "
          "expected_volume, path.");
    m.def(
        "presets",
        [] {
            py::dict out;
            for (const geom::PresetInfo& p : geom::preset_list()) out[py::str(p.name)] = p.description;
            return out;
        },
        "The built-in blocks: name -> description.");
}
