#pragma once
// Where a run's files go: checks made before any work (so a bad path fails in a second, not
// after the mesh) and the atomic write of a text file. Shared by `tubemesh mesh` and Python.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/io/mesh_io.hpp"
#include "engine/pipeline/pipeline.hpp"
#include "job/mesh_settings.hpp"

namespace tubemesh::job {

// ".MSH" -> ".msh"
std::string lower_extension(const std::string& path);

// A file can be created there: its folder exists and is writable, and it is not a folder.
// Throws tubemesh::Error naming the path and what is wrong.
void require_writable(const std::string& path);

// The .inp element families and pyramid forms by name, the default first.
inline const std::vector<std::string> kInpFamilies = {"stress", "heat", "coupled", "coupled-abaqus"};
inline const std::vector<std::string> kInpPyramids = {"hex", "c3d5"};

// How mesh files are written: .msh as text or binary, the .inp family and pyramid form by the
// names above. Throws tubemesh::Error for an unknown name or c3d5 outside the stress family.
WriteOptions write_options(bool msh_ascii, const std::string& inp_family, const std::string& inp_pyramid,
                           Naming naming);

// The water networks of a run's .inp files (engine/io/inp_network.hpp): the options checked,
// the films files ("x.films.inp") added to `outputs` for the distinctness check. Throws
// tubemesh::Error, naming the option, for a non-positive or non-finite coefficient, a pipe
// number below 1, a film coefficient or reversed flow without the network, or the network
// without a .inp among `outputs`.
PipeNetworkOptions pipe_network_options(bool write, std::optional<double> film_coefficient,
                                        const std::vector<int>& reverse_flow, std::vector<std::string>& outputs,
                                        Naming naming);

// A mesh file of a format tubemesh writes (.msh, .vtu, .vtm, .inp) that can hold a mesh of this
// stage (.inp needs every boundary face on a cell), at a writable place.
void check_mesh_output(const std::string& path, Stage stage);

// A report file with this extension (".json", ".html") at a writable place; `what` names it
// in the error ("the report", "the HTML report").
void check_report_output(const std::string& path, const char* extension, const char* what);

// No two of a run's files are one: the same file named twice (also through "..", "." or a
// link), a file inside the folder where a .vtm writes its parts, or two .vtm files that share
// that folder. Throws tubemesh::Error naming both; call it before any work.
void check_distinct_outputs(const std::vector<std::string>& paths);

// Written to a temporary name and renamed (engine/io/atomic_file.hpp).
void write_text(const std::string& path, const std::string& text);

// A run's files, all or none: the mesh to every path in `meshes`, then each text to its path,
// each complete under a temporary name before any target is replaced (io::CommitGroup), so a
// failure or an interrupt leaves every target as it was, files that existed before included.
void write_all(const HybridMesh& mesh, const std::vector<std::string>& meshes, const WriteOptions& options,
               const std::vector<std::pair<std::string, std::string>>& texts);

}  // namespace tubemesh::job
