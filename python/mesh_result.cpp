#include "python/mesh_result.hpp"

#include <pybind11/stl.h>

#include <filesystem>
#include <optional>
#include <vector>

#include "engine/io/mesh_io.hpp"
#include "job/assembly_report.hpp"
#include "job/html_report.hpp"
#include "job/job_settings.hpp"
#include "job/option_table.hpp"
#include "python/option_keywords.hpp"
#include "job/mesh_report.hpp"
#include "job/outputs.hpp"
#include "job/quality_measures.hpp"

namespace tubemesh::python {

namespace py = pybind11;

namespace {

// A read-only array over `data` (rows x columns, C order) that keeps `owner` alive.
template <class T>
py::array view(const std::vector<T>& data, py::ssize_t columns, const py::object& owner) {
    const py::ssize_t rows = static_cast<py::ssize_t>(data.size()) / columns;
    py::array a = columns == 1 ? py::array_t<T>({rows}, {py::ssize_t(sizeof(T))}, data.data(), owner)
                               : py::array_t<T>({rows, columns}, {py::ssize_t(sizeof(T)) * columns, py::ssize_t(sizeof(T))},
                                                data.data(), owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

MeshResult& result_of(const py::object& self) { return self.cast<MeshResult&>(); }

// The report as `tubemesh mesh --report` writes it, without the list of files.
nlohmann::json report_json(const MeshResult& r) {
    nlohmann::json report = job::run_json(r.run, {});
    if (r.assembly) report["assembly"] = job::assembly_json(*r.assembly, r.run);
    return report;
}
const HybridMesh& mesh_of(const py::object& self) { return result_of(self).run.result.mesh; }

py::object cells(const py::object& self, CellKind kind) {
    return view(mesh_of(self).block(kind).nodes, node_count(kind), self);
}

py::object faces(const py::object& self, FaceKind kind) {
    return view(mesh_of(self).block(kind).nodes, face_size(kind), self);
}

py::object nodes(const py::object& self) {
    MeshResult& r = result_of(self);
    if (!r.nodes) {
        const HybridMesh& m = r.run.result.mesh;
        py::array_t<double> xyz({py::ssize_t(m.point_count()), py::ssize_t(3)});
        auto out = xyz.mutable_unchecked<2>();
        for (index_t i = 0; i < m.point_count(); ++i) {
            out(i, 0) = m.x[i];
            out(i, 1) = m.y[i];
            out(i, 2) = m.z[i];
        }
        py::detail::array_proxy(xyz.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
        r.nodes = xyz;
    }
    return r.nodes;
}

// {kind: {measure: array}} over every measure of quality_measures.hpp.
py::object quality(const py::object& self) {
    MeshResult& r = result_of(self);
    if (!r.quality) {
        py::dict out;
        for (const job::QualityMeasure& m : job::quality_measures()) {
            std::vector<double> values;
            {
                py::gil_scoped_release release;
                values = m.values(r.run.result.mesh);
            }
            if (!out.contains(m.kind_key)) out[m.kind_key] = py::dict();
            out[m.kind_key][m.key] = py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
        }
        r.quality = out;
    }
    return r.quality;
}

py::object report(const py::object& self) {
    MeshResult& r = result_of(self);
    if (!r.report) r.report = py::module_::import("json").attr("loads")(report_json(r).dump());
    return r.report;
}

// The indices of the members of every group, by the array they index:
// regions {"tets": [...], "pyramids": [...], "hexes": [...]} and surface groups
// {"triangles": [...], "quads": [...]}, each only where the group has members.
py::object groups(const py::object& self) {
    MeshResult& r = result_of(self);
    if (r.groups) return r.groups;
    const HybridMesh& m = r.run.result.mesh;
    py::dict out;
    auto add_members = [&](const std::vector<std::string>& names, const std::vector<index_t>& ids, const char* array) {
        std::vector<std::vector<index_t>> members(names.size());
        for (std::size_t i = 0; i < ids.size(); ++i) members[ids[i]].push_back(static_cast<index_t>(i));
        for (std::size_t g = 0; g < names.size(); ++g) {
            if (members[g].empty()) continue;
            if (!out.contains(names[g])) out[py::str(names[g])] = py::dict();
            out[py::str(names[g])][array] =
                py::array_t<index_t>(static_cast<py::ssize_t>(members[g].size()), members[g].data());
        }
    };
    add_members(m.region_names, m.block(CellKind::Tet).region, "tets");
    add_members(m.region_names, m.block(CellKind::Pyramid).region, "pyramids");
    add_members(m.region_names, m.block(CellKind::Hex).region, "hexes");
    add_members(m.surface_group_names, m.block(FaceKind::Tri).group, "triangles");
    add_members(m.surface_group_names, m.block(FaceKind::Quad).group, "quads");
    r.groups = out;
    return out;
}

// The write options of mesh() unless given here (None: mesh()'s).
void write(const py::object& self, const py::object& path, const py::kwargs& keywords) {
    const std::string p = py::str(py::module_::import("os").attr("fspath")(path));
    const MeshResult& r = result_of(self);
    job::check_mesh_output(p, r.run.result.reached);
    nlohmann::json given = r.given;
    const nlohmann::json here = given_options(keywords);
    for (const auto& [key, value] : here.items()) {
        const job::OptionSpec* spec = job::find_option(key);
        if (!spec->help.starts_with("With pipe_network") && key != "msh_ascii" && key != "inp_family" &&
            key != "inp_pyramid" && key != "pipe_network")
            throw Error("write() takes the write options msh_ascii, inp_family, inp_pyramid, pipe_network, "
                        "film_coefficient and reverse_flow, got " + key);
        given[key] = value;
    }
    const job::JobSettings settings = job::job_settings(given, job::Naming::Keywords);
    std::vector<std::string> files{p};
    WriteOptions options = job::job_write_options(settings, files, job::Naming::Keywords);
    options.description = &r.run.result.description;
    py::gil_scoped_release release;
    write_mesh(r.run.result.mesh, p, options);
}

void write_text(const py::object& self, const py::object& path, const char* extension, const char* what,
                std::string (*text)(const MeshResult&)) {
    const std::string p = py::str(py::module_::import("os").attr("fspath")(path));
    job::check_report_output(p, extension, what);
    const MeshResult& r = result_of(self);
    py::gil_scoped_release release;
    job::write_text(p, text(r));
}



}  // namespace

void bind_mesh_result(py::module_& m) {
    py::class_<MeshResult>(m, "Mesh", R"doc(A checked hybrid mesh and the report of the run that made it (tubemesh.mesh).

Arrays are numpy arrays. Cell arrays (tets n x 4, pyramids n x 5, hexes n x 8, uint32, 0-based
node indices in VTK / Gmsh node order) and the boundary faces (triangles, quads) view the mesh
store without copying and are read-only; x, y, z view the store's coordinates the same way.
nodes (n x 3 float64) is a copy of x, y, z (the store keeps them apart), made on first use.)doc")
        .def_property_readonly("nodes", &nodes, "Node coordinates, n x 3 float64 (a copy of x, y, z, made once)")
        .def_property_readonly("x", [](py::object self) { return view(mesh_of(self).x, 1, self); },
                               "x of every node (a view, no copy)")
        .def_property_readonly("y", [](py::object self) { return view(mesh_of(self).y, 1, self); },
                               "y of every node (a view, no copy)")
        .def_property_readonly("z", [](py::object self) { return view(mesh_of(self).z, 1, self); },
                               "z of every node (a view, no copy)")
        .def_property_readonly("tets", [](py::object self) { return cells(self, CellKind::Tet); },
                               "Tetrahedra, n x 4 node indices (a view)")
        .def_property_readonly("pyramids", [](py::object self) { return cells(self, CellKind::Pyramid); },
                               "Pyramids, n x 5 node indices, base 0-3 then apex (a view)")
        .def_property_readonly("hexes", [](py::object self) { return cells(self, CellKind::Hex); },
                               "Hexahedra, n x 8 node indices, bottom 0-3 then top 4-7 (a view)")
        .def_property_readonly("triangles", [](py::object self) { return faces(self, FaceKind::Tri); },
                               "Boundary triangles, n x 3 node indices, normal out of the solid (a view)")
        .def_property_readonly("quads", [](py::object self) { return faces(self, FaceKind::Quad); },
                               "Boundary quads, n x 4 node indices, normal out of the solid (a view)")
        .def_property_readonly("groups", &groups,
                               "Group name -> {array name: indices into that array}: volume regions ('hex_ring', "
                               "'pyramids', 'tets') index tets / pyramids / hexes, surface groups ('pipe_1', "
                               "'face_3', ...) index triangles / quads")
        .def_property_readonly("quality", &quality,
                               "Per kind, per measure, one value per cell: {'tet': {'collapse', 'scaled_jacobian', "
                               "'min_dihedral_degrees', 'aspect_ratio'}, 'pyramid': {'scaled_jacobian'}, 'hex': "
                               "{'scaled_jacobian' (J_m), 'condition', 'verdict_scaled_jacobian'}}: the report's "
                               "quality keys")
        .def_property_readonly("report", &report,
                               "The run's report as a dict: what `tubemesh mesh --report` writes as JSON")
        .def("write", &write, py::arg("path"),
             "write(path, *, msh_ascii, inp_family, inp_pyramid, pipe_network, film_coefficient, reverse_flow): "
             "writes the mesh; the format by extension: .msh (Gmsh 4.1, binary unless msh_ascii), .vtu, .vtm, .inp. "
             "The write options are tubemesh.mesh()'s (see its help), by default the ones given to it. Written to "
             "a temporary name and renamed.")
        .def(
            "write_report", [](py::object self, py::object path) {
                write_text(self, path, ".json", "the report",
                           [](const MeshResult& r) { return report_json(r).dump(2) + "\n"; });
            },
            py::arg("path"), "Writes the report as JSON (as `tubemesh mesh --report`)")
        .def(
            "write_html", [](py::object self, py::object path) {
                write_text(self, path, ".html", "the HTML report",
                           [](const MeshResult& r) { return job::html_report(r.run); });
            },
            py::arg("path"), "Writes the report as one self-contained HTML page (as `tubemesh mesh --html`)")
        .def("__repr__", [](py::object self) {
            const HybridMesh& m = mesh_of(self);
            return "<tubemesh.Mesh " + result_of(self).run.source + ": " + std::to_string(m.point_count()) +
                   " nodes, " + std::to_string(m.cell_count(CellKind::Hex)) + " hexes, " +
                   std::to_string(m.cell_count(CellKind::Pyramid)) + " pyramids, " +
                   std::to_string(m.cell_count(CellKind::Tet)) + " tets>";
        });
}

}  // namespace tubemesh::python
