#pragma once
// Whole-file input: readers parse from memory, which makes bounds checks simple and lets the
// fuzz tests feed them corrupted bytes without touching the disk.
#include <filesystem>
#include <string>

namespace tubemesh::io {

// Throws tubemesh::Error naming the path and the system's reason when the file cannot be read.
std::string read_file_bytes(const std::filesystem::path& path);

}  // namespace tubemesh::io
