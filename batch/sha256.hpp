#pragma once
// SHA-256 digests as lower-case hex, from OpenSSL's EVP interface: the catalogue's input,
// options and output hashes.
#include <filesystem>
#include <string>
#include <string_view>

namespace tubemesh::batch {

std::string sha256_hex(std::string_view bytes);

// Throws tubemesh::Error naming the file when it cannot be read.
std::string sha256_file(const std::filesystem::path& path);

}  // namespace tubemesh::batch
