#include "job/outputs.hpp"

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "engine/io/atomic_file.hpp"
#include "engine/io/inp_network.hpp"

namespace tubemesh::job {

namespace fs = std::filesystem;

std::string lower_extension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

void require_writable(const std::string& path) {
    const fs::path p(path);
    const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw Error("cannot write '" + path + "': the folder '" + dir.string() + "' does not exist");
    if (::access(dir.c_str(), W_OK) != 0)
        throw Error("cannot write '" + path + "': the folder '" + dir.string() + "' is not writable");
    if (fs::is_directory(p, ec)) throw Error("cannot write '" + path + "': it is a folder");
}

void check_mesh_output(const std::string& path, Stage stage) {
    const std::string ext = lower_extension(path);
    if (ext != ".msh" && ext != ".vtu" && ext != ".vtm" && ext != ".inp")
        throw Error("cannot write '" + path + "': unknown mesh format (use .msh, .vtu, .vtm or .inp)");
    if (ext == ".inp" && (stage == Stage::Surface || stage == Stage::Pyramids))
        throw Error("cannot write '" + path + "': Abaqus .inp needs every boundary face on a cell, which a " +
                    stage_name(stage) + "-stage mesh does not have yet (use .msh or .vtu)");
    require_writable(path);
}

namespace {

// The path with its existing part resolved (links, "..", "."), for comparing outputs.
fs::path resolved(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? fs::absolute(path).lexically_normal() : p;
}

// The folder of a .vtm's parts: beside it, named after its stem (engine/io/vtu_writer.cpp).
fs::path parts_folder(const fs::path& vtm) { return vtm.parent_path() / vtm.stem(); }

bool inside(const fs::path& file, const fs::path& folder) {
    for (fs::path p = file.parent_path(); !p.empty() && p != p.root_path(); p = p.parent_path())
        if (p == folder) return true;
    return false;
}

}  // namespace

void check_distinct_outputs(const std::vector<std::string>& paths) {
    std::vector<fs::path> real;
    for (const std::string& p : paths) real.push_back(resolved(p));
    for (std::size_t i = 0; i < paths.size(); ++i)
        for (std::size_t j = 0; j < paths.size(); ++j) {
            if (i == j) continue;
            const bool vtm_i = lower_extension(paths[i]) == ".vtm", vtm_j = lower_extension(paths[j]) == ".vtm";
            std::error_code ec;
            if (i < j && (real[i] == real[j] || fs::equivalent(real[i], real[j], ec)))
                throw Error("cannot write '" + paths[j] + "': it is the same file as '" + paths[i] +
                            "'; give each output its own name");
            if (vtm_i && inside(real[j], parts_folder(real[i])))
                throw Error("cannot write '" + paths[j] + "': it is inside '" + parts_folder(paths[i]).string() +
                            "', where '" + paths[i] + "' writes its parts; give it another folder");
            if (i < j && vtm_i && vtm_j && parts_folder(real[i]) == parts_folder(real[j]))
                throw Error("cannot write '" + paths[j] + "': '" + paths[i] +
                            "' writes its parts to the same folder '" + parts_folder(paths[i]).string() +
                            "'; give one of them another name");
        }
}

WriteOptions write_options(bool msh_ascii, const std::string& inp_family, const std::string& inp_pyramid,
                           Naming naming) {
    const std::string family = option_name("inp_family", naming), pyramid = option_name("inp_pyramid", naming);
    auto check_member = [&](const std::string& value, const std::vector<std::string>& names, const std::string& name) {
        for (const std::string& n : names)
            if (n == value) return;
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        throw Error(name + " " + value + ": not one of " + list);
    };
    check_member(inp_family, kInpFamilies, family);
    check_member(inp_pyramid, kInpPyramids, pyramid);
    WriteOptions o;
    o.msh_encoding = msh_ascii ? MshEncoding::Ascii : MshEncoding::Binary;
    o.inp_family = inp_family == "heat"             ? InpFamily::HeatTransfer
                   : inp_family == "coupled"        ? InpFamily::Coupled
                   : inp_family == "coupled-abaqus" ? InpFamily::CoupledAbaqus
                                                    : InpFamily::Stress;
    o.inp_pyramid = inp_pyramid == "c3d5" ? InpPyramid::C3D5 : InpPyramid::CollapsedHex;
    if (o.inp_pyramid == InpPyramid::C3D5 && o.inp_family != InpFamily::Stress)
        throw Error(pyramid + " c3d5 has no heat-transfer or coupled variant: use " + pyramid + " hex with " + family +
                    " " + inp_family);
    return o;
}

PipeNetworkOptions pipe_network_options(bool write, std::optional<double> film_coefficient,
                                        const std::vector<int>& reverse_flow, std::vector<std::string>& outputs,
                                        Naming naming) {
    const std::string network = option_name("pipe_network", naming), film = option_name("film_coefficient", naming),
                      reverse = option_name("reverse_flow", naming);
    PipeNetworkOptions o;
    if (!write) {
        if (film_coefficient) throw Error(film + " is for the water network: add " + network);
        if (!reverse_flow.empty()) throw Error(reverse + " is for the water network: add " + network);
        return o;
    }
    o.write = true;
    if (film_coefficient) {
        if (!std::isfinite(*film_coefficient) || *film_coefficient <= 0)
            throw Error(fmt::format("{} must be a positive number, got {}", film, *film_coefficient));
        o.film_coefficient = *film_coefficient;
    }
    for (int k : reverse_flow)
        if (k < 1) throw Error(reverse + " " + std::to_string(k) + ": pipes are numbered from 1 (pipe_1)");
    o.reverse_flow = reverse_flow;
    std::vector<std::string> films;
    for (const std::string& out : outputs)
        if (lower_extension(out) == ".inp") films.push_back(io::films_path(out).string());
    if (films.empty()) throw Error(network + " writes the water into a .inp: give an output ending in .inp");
    outputs.insert(outputs.end(), films.begin(), films.end());
    return o;
}

void check_report_output(const std::string& path, const char* extension, const char* what) {
    if (lower_extension(path) != extension)
        throw Error("cannot write " + std::string(what) + " '" + path + "': it must end in " + extension);
    require_writable(path);
}

void write_text(const std::string& path, const std::string& text) {
    io::AtomicFile file(path);
    file.write(text);
    file.commit();
}

void write_all(const HybridMesh& mesh, const std::vector<std::string>& meshes, const WriteOptions& options,
               const std::vector<std::pair<std::string, std::string>>& texts) {
    io::CommitGroup group;
    for (const std::string& out : meshes) write_mesh(mesh, out, options);
    for (const auto& [path, text] : texts) write_text(path, text);
    group.commit();
}

}  // namespace tubemesh::job
