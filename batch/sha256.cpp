#include "batch/sha256.hpp"

#include <openssl/evp.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "engine/core/types.hpp"
#include "engine/io/file_bytes.hpp"

namespace tubemesh::batch {

namespace {

class Digest {
public:
    Digest() : ctx_(EVP_MD_CTX_new(), EVP_MD_CTX_free) {
        if (!ctx_ || EVP_DigestInit_ex(ctx_.get(), EVP_sha256(), nullptr) != 1)
            throw Error("internal error: OpenSSL cannot start a SHA-256 digest");
    }
    void update(const void* data, std::size_t size) {
        if (EVP_DigestUpdate(ctx_.get(), data, size) != 1) throw Error("internal error: OpenSSL SHA-256 update failed");
    }
    std::string hex() {
        std::array<unsigned char, EVP_MAX_MD_SIZE> md{};
        unsigned int size = 0;
        if (EVP_DigestFinal_ex(ctx_.get(), md.data(), &size) != 1)
            throw Error("internal error: OpenSSL SHA-256 final failed");
        static constexpr char kHex[] = "0123456789abcdef";
        std::string out;
        for (unsigned int i = 0; i < size; ++i) {
            out += kHex[md[i] >> 4];
            out += kHex[md[i] & 15];
        }
        return out;
    }

private:
    std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx_;
};

}  // namespace

std::string sha256_hex(std::string_view bytes) {
    Digest d;
    d.update(bytes.data(), bytes.size());
    return d.hex();
}

std::string sha256_file(const std::filesystem::path& path) {
    io::require_regular_file(path);
    std::unique_ptr<std::FILE, decltype(&std::fclose)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!f) throw Error("cannot read '" + path.string() + "': " + std::strerror(errno));
    Digest d;
    std::array<char, 1 << 16> buffer;
    std::size_t n;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), f.get())) > 0) d.update(buffer.data(), n);
    if (std::ferror(f.get())) throw Error("cannot read '" + path.string() + "': read error");
    return d.hex();
}

}  // namespace tubemesh::batch
