#include "batch/worker.hpp"

#include <unistd.h>

#include <cerrno>
#include <exception>
#include <iostream>
#include <iterator>
#include <string>

#include "batch/block_options.hpp"
#include "batch/sha256.hpp"
#include "batch/test_hooks.hpp"
#include "engine/core/types.hpp"
#include "engine/io/file_bytes.hpp"
#include "geom/builders/block_builder.hpp"
#include "geom/builders/spec_json.hpp"
#include "geom/import/import.hpp"
#include "geom/mesh_file.hpp"
#include "geom/prepare.hpp"
#include "geom/working_scale.hpp"
#include "job/mesh_job.hpp"
#include "job/outputs.hpp"

namespace tubemesh::batch {

namespace {

namespace fs = std::filesystem;

nlohmann::json input_json(const BlockEntry& b) {
    if (!b.cad.empty()) return {{"cad", b.cad.string()}};
    return {{"spec_text", b.spec_text}, {"spec_source", b.spec_source}};
}

geom::BlockSpec request_spec(const nlohmann::json& r) {
    const std::string source = r.at("spec_source").get<std::string>();
    std::string text = r.at("spec_text").get<std::string>();
    if (text.empty()) text = io::read_file_bytes(source);  // the manifest could not read it: say why
    return geom::parse_block_spec(text, source);
}

geom::Model request_model(const nlohmann::json& r, int solid) {
    if (r.contains("cad")) {
        geom::ImportOptions import;
        import.solid = solid;
        return geom::import_model(r.at("cad").get<std::string>(), import);
    }
    return geom::build_block(request_spec(r)).model;
}

// Temporaries a killed writer left beside a target (engine/io/atomic_file.cpp names them
// ".<name>.tmp-<pid>-<n>"): the block is being redone, so nobody else writes them.
void remove_stale_temporaries(const fs::path& target) {
    const std::string prefix = "." + target.filename().string() + ".tmp-";
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(target.parent_path(), ec))
        if (e.path().filename().string().starts_with(prefix)) fs::remove(e.path(), ec);
}

nlohmann::json measure(const MeasureSummary& m) { return {{"min", m.min}, {"mean", m.mean}, {"max", m.max}}; }

nlohmann::json estimate(const nlohmann::json& r) {
    const nlohmann::json& o = r.at("options");
    const geom::Model model = request_model(r, solid_of(o));
    const geom::PrepareOptions prepare =
        geom::prepare_options(geom::working_options(mesh_options(o, 1), model.scale_exponent()));
    const geom::TubeSearch found = geom::find_tubes(model, prepare.tubes);
    const geom::SizePlan plan = geom::plan_sizes(model, found.tubes, prepare.sizing);
    return {{"status", "done"}, {"estimate", geom::estimate_run_elements(model, found, plan, prepare).total()}};
}

nlohmann::json mesh(const nlohmann::json& r) {
    const std::string id = r.at("id").get<std::string>();
    const int attempt = r.value("attempt", 1);
    worker_fault_point("start", id, attempt);
    worker_fault_point("crash", id, attempt);
    worker_fault_point("hang", id, attempt);
    worker_fault_point("die-once", id, attempt);

    const nlohmann::json& o = r.at("options");
    const std::vector<std::string> outputs = r.at("outputs").get<std::vector<std::string>>();
    job::JobSettings settings = settings_of(o);
    settings.mesh.threads = r.at("threads").get<int>();
    for (const std::string& out : outputs) {
        if (job::lower_extension(out) != ".html") settings.outputs.push_back(out);
        else settings.html = out;  // the HTML report is written as text
    }
    settings.report = r.at("report").get<std::string>();
    for (const std::string& out : outputs) remove_stale_temporaries(out);
    remove_stale_temporaries(settings.report);

    job::JobSource source;
    if (r.contains("cad")) source.cad = r.at("cad").get<std::string>();
    else source.spec = request_spec(r);
    const job::JobResult job = job::run_mesh_job(source, settings, {.naming = job::Naming::Keywords});
    const geom::MeshRun& meshed = job.run;
    worker_fault_point("written", id, attempt);

    const PipelineResult& p = meshed.result;
    const HybridMesh& m = p.mesh;
    nlohmann::json files = nlohmann::json::array();
    for (const std::string& out : outputs)
        files.push_back({{"path", fs::path(out).filename().string()}, {"bytes", fs::file_size(out)}, {"sha256", sha256_file(out)}});
    nlohmann::json phases = nlohmann::json::array();
    for (const PhaseReport& ph : p.phases) phases.push_back({ph.name, ph.seconds});
    return {{"status", "done"},
            {"nodes", m.point_count()},
            {"hexes", m.cell_count(CellKind::Hex)},
            {"pyramids", m.cell_count(CellKind::Pyramid)},
            {"tets", m.cell_count(CellKind::Tet)},
            {"quality",
             {{"tet_collapse", measure(p.quality.tet_collapse)},
              {"pyramid_scaled_jacobian", measure(p.quality.pyramid_jacobian)},
              {"hex_scaled_jacobian", measure(p.quality.hex_scaled_jacobian)},
              {"hex_condition", measure(p.quality.hex_condition)}}},
            {"phases", phases},
            {"seconds", p.seconds},
            {"outputs", files},
            {"report", fs::path(settings.report).filename().string()}};
}

bool write_all(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

}  // namespace

nlohmann::json mesh_request(const BlockEntry& b, const fs::path& outdir, int threads, int attempt) {
    nlohmann::json outputs = nlohmann::json::array();
    for (const nlohmann::json& f : b.options.at("formats"))
        outputs.push_back((outdir / (b.id + "." + f.get<std::string>())).string());
    nlohmann::json r = input_json(b);
    r.update({{"mode", "mesh"},
              {"id", b.id},
              {"options", b.options},
              {"threads", threads},
              {"outputs", outputs},
              {"report", (outdir / (b.id + ".report.json")).string()},
              {"attempt", attempt}});
    return r;
}

nlohmann::json estimate_request(const BlockEntry& b) {
    nlohmann::json r = input_json(b);
    r.update({{"mode", "estimate"}, {"id", b.id}, {"options", b.options}});
    return r;
}

nlohmann::json run_request(const nlohmann::json& request) {
    nlohmann::json result;
    try {
        result = request.at("mode") == "estimate" ? estimate(request) : mesh(request);
    } catch (const Error& e) {
        result = {{"status", "failed"}, {"error", e.what()}};
    } catch (const std::exception& e) {
        result = {{"status", "failed"}, {"error", std::string("internal error: ") + e.what()}};
    }
    result["worker"] = "pid " + std::to_string(::getpid());
    return result;
}

int worker_main() {
    nlohmann::json request;
    try {
        request = nlohmann::json::parse(std::string(std::istreambuf_iterator<char>(std::cin), {}));
    } catch (const std::exception& e) {
        std::cerr << "tubemesh worker: unreadable request: " << e.what() << "\n";
        return 2;
    }
    const nlohmann::json result = run_request(request);
    return write_all(kResultFd, result.dump()) ? 0 : 2;
}

BlockRecord record_from_result(const BlockEntry& b, const nlohmann::json& result) {
    BlockRecord r;
    r.id = b.id;
    r.position = b.position;
    r.input_hash = b.input_hash;
    r.options_hash = b.options_hash;
    r.status = result.value("status", "failed") == "done" ? "done" : "failed";
    r.error = result.value("error", "");
    r.worker = result.value("worker", "");
    if (r.status != "done") return r;
    r.nodes = result.at("nodes").get<std::int64_t>();
    r.hexes = result.at("hexes").get<std::int64_t>();
    r.pyramids = result.at("pyramids").get<std::int64_t>();
    r.tets = result.at("tets").get<std::int64_t>();
    const nlohmann::json& q = result.at("quality");
    auto m = [&](const char* k) { return MeasureRecord{q.at(k).at("min").get<double>(), q.at(k).at("mean").get<double>()}; };
    r.tet_collapse = m("tet_collapse");
    r.pyramid_jacobian = m("pyramid_scaled_jacobian");
    r.hex_jacobian = m("hex_scaled_jacobian");
    r.hex_condition_max = q.at("hex_condition").at("max").get<double>();
    for (const nlohmann::json& ph : result.at("phases"))
        r.phases.emplace_back(ph.at(0).get<std::string>(), ph.at(1).get<double>());
    r.seconds = result.at("seconds").get<double>();
    for (const nlohmann::json& f : result.at("outputs"))
        r.outputs.push_back({f.at("path").get<std::string>(), f.at("bytes").get<std::uint64_t>(),
                             f.at("sha256").get<std::string>()});
    r.report = result.at("report").get<std::string>();
    return r;
}

}  // namespace tubemesh::batch
