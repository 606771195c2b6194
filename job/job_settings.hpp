#pragma once
// A mesh job's settings from the options a user gave, by the option table's keys
// (job/option_table.hpp): the meshing settings, the files to write and how. Every front end
// collects what was given as {key: value} and calls job_settings, so all take the same values
// with the same defaults and refuse the same ones with the same message.
#include <nlohmann/json.hpp>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/io/mesh_io.hpp"
#include "job/mesh_settings.hpp"

namespace tubemesh::job {

struct JobSettings {
    MeshSettings mesh;
    bool assembly = false;
    double glue_tolerance = 0;          // 0: automatic
    std::vector<std::string> outputs;   // mesh files, format by extension
    std::string report, html;           // "" : none
    bool msh_ascii = false;
    std::string inp_family, inp_pyramid;
    bool pipe_network = false;
    std::optional<double> film_coefficient;
    std::vector<int> reverse_flow;
    bool quiet = false;
};

// `given`: {key: value} of the options given, under the table's keys, types checked
// (check_option_type); null is "not given". The rest take the table's defaults; economy sets
// what it sets only where not given. Throws tubemesh::Error naming the option (as `naming`
// spells it) for a value out of its range.
JobSettings job_settings(const nlohmann::json& given, Naming naming);

// The options a front end got under any spelling, as job_settings takes them: aliases turned
// into their option's key and value, each older spelling passed to `warn` with its deprecation
// message. Throws tubemesh::Error "<where>: unknown option \"x\"" for a name `where` does not show.
nlohmann::json canonical_options(const nlohmann::json& named, unsigned where, const std::string& context,
                                 const std::function<void(const std::string&)>& warn);

// How the job's mesh files are written; the films files of a pipe network are added to `files`
// (for the distinctness check).
WriteOptions job_write_options(const JobSettings& settings, std::vector<std::string>& files, Naming naming);

}  // namespace tubemesh::job
