#include "tools/run/outputs.hpp"

#include <unistd.h>

#include <cctype>
#include <filesystem>

#include "engine/io/atomic_file.hpp"

namespace tubemesh::run {

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
    o.inp_family = inp_family == "heat"      ? InpFamily::HeatTransfer
                   : inp_family == "coupled" ? InpFamily::Coupled
                                             : InpFamily::Stress;
    o.inp_pyramid = inp_pyramid == "c3d5" ? InpPyramid::C3D5 : InpPyramid::CollapsedHex;
    if (o.inp_pyramid == InpPyramid::C3D5 && o.inp_family != InpFamily::Stress)
        throw Error(pyramid + " c3d5 has no heat-transfer or coupled variant: use " + pyramid + " hex with " + family +
                    " " + inp_family);
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

}  // namespace tubemesh::run
