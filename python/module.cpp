// The Python module `tubemesh`: mesh(), check(), make_block(), presets() and the Mesh result
// (mesh_result.hpp). Options (job/option_table.hpp, python/option_keywords.hpp), defaults,
// messages, the job and its reports are the CLI's own (job/), so `tubemesh.mesh(...)` and `tubemesh mesh ...` take the same values and
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
#include "job/job_settings.hpp"
#include "job/mesh_job.hpp"
#include "python/option_keywords.hpp"

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

std::unique_ptr<MeshResult> mesh(const py::object& source, const py::dict& keywords, const py::object& progress) {
    auto result = std::make_unique<MeshResult>();
    result->given = given_options(keywords);
    const job::JobSettings settings = job::job_settings(result->given, job::Naming::Keywords);
    const std::string name = path_text(source);
    job::JobSource from;
    if (is_preset(name) && !std::filesystem::exists(name) && !settings.assembly)
        from.preset = name;
    else
        from.cad = name;

    InterruptListener listener(progress);
    bool interrupted = false;
    {
        py::gil_scoped_release release;
        try {
            job::JobResult job =
                job::run_mesh_job(from, settings, {.progress = listener.callback(), .naming = job::Naming::Keywords});
            result->run = std::move(job.run);
            result->assembly = std::move(job.assembly);
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

    tp::define_with_options(
        m, "mesh",
        py::cpp_function(&tp::mesh, py::arg("source"), py::arg("options"), py::arg("progress")), "paper-ex1",
        "Meshes a CAD file (.step .stp .iges .igs .brep) or a built-in block (a preset name, see presets()).\n\n"
        "The options are `tubemesh mesh`'s (README, \"Options\"), with the same defaults and ranges; output, "
        "report and html write the files (all or none) before returning.",
        "progress: a callable (phase, done, total), called with the GIL from the meshing threads.\n\n"
        "Returns a tubemesh.Mesh. Raises tubemesh.Error with the CLI's one-line message; the GIL is released "
        "while meshing; Ctrl-C (KeyboardInterrupt) stops the run within a phase's next progress step.");
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
