#pragma once
// The mesh job, once for every front end (the command line, the batch workers and so the MPI
// driver, the Python module): settings -> source -> mesh -> checked outputs -> reports.
//
// Every file is checked before any work (format, folder, no two outputs one file); the mesh
// passes its stage's check (engine/pipeline/stage_check.hpp) inside the pipeline; the mesh files
// and reports are written all or none (job/outputs.hpp: write_all). Any error is a
// tubemesh::Error and leaves no file.
#include <functional>
#include <optional>
#include <string>

#include "geom/assembly/mesh_assembly.hpp"
#include "geom/builders/block_spec.hpp"
#include "geom/mesh_file.hpp"
#include "job/job_settings.hpp"

namespace tubemesh::job {

// Where the mesh comes from: exactly one of a CAD file, a block spec and a preset name.
struct JobSource {
    std::string cad;
    std::optional<geom::BlockSpec> spec;
    std::string preset;
};

struct JobHooks {
    // Every progress event of the run; may throw to stop it (the Python module's Ctrl-C).
    ProgressCallback progress;
    // Polled at every progress event: true stops the run with job::Stopped.
    std::function<bool()> stop;
    // After the checks, before any work: a front end's last word on the engine's options (the
    // command line's memory limit).
    std::function<void(MeshOptions&)> before_mesh;
    // Names options in messages as flags or as keywords.
    Naming naming = Naming::Flags;
};

// Thrown through the run when JobHooks::stop said so.
struct Stopped {};

struct JobResult {
    geom::MeshRun run;
    std::optional<geom::AssemblyRun> assembly;  // with settings.assembly
    WriteOptions write;                         // how the files were written (the mesh's description aside)
};

// Checks the outputs, meshes the source with the settings, writes every output and report
// (JSON, HTML) all or none. The report lists the mesh files and the HTML report.
JobResult run_mesh_job(const JobSource& source, const JobSettings& settings, const JobHooks& hooks = {});

// The engine's options for the settings with the hooks' progress and stop.
MeshOptions job_mesh_options(const JobSettings& settings, const JobHooks& hooks);

}  // namespace tubemesh::job
