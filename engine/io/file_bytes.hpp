#pragma once
// Whole-file input: readers parse from memory, which makes bounds checks simple and lets the
// fuzz tests feed them corrupted bytes without touching the disk.
#include <filesystem>
#include <string>

namespace tubemesh::io {

// Throws tubemesh::Error naming the path and the system's reason when the file cannot be read.
std::string read_file_bytes(const std::filesystem::path& path);

// Throws tubemesh::Error for a path that exists but is no regular file (a folder, a device, a
// FIFO): reading one could block or never end. A missing path passes (opening it says why).
void require_regular_file(const std::filesystem::path& path);

}  // namespace tubemesh::io
