#include "engine/io/file_bytes.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>
#include <utility>

#include "engine/core/types.hpp"

namespace tubemesh::io {

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, int error_number) {
    throw Error("cannot read '" + path.string() + "': " + std::generic_category().message(error_number));
}

// Closes the descriptor on every path out of read_file_bytes.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

void require_regular_file(const std::filesystem::path& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) return;
    if (S_ISDIR(info.st_mode)) fail(path, EISDIR);
    if (!S_ISREG(info.st_mode)) throw Error("cannot read '" + path.string() + "': it is not a regular file");
}

std::string read_file_bytes(const std::filesystem::path& path) {
    require_regular_file(path);  // before open(): opening a FIFO blocks
    Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
    if (file.fd < 0) fail(path, errno);
    struct stat info {};
    if (::fstat(file.fd, &info) != 0) fail(path, errno);

    // The size is a hint only: read until end of file whatever it says. One spare byte lets
    // the final zero-byte read happen without growing the buffer.
    std::string bytes;
    bytes.resize(info.st_size > 0 ? static_cast<std::size_t>(info.st_size) + 1 : std::size_t{4096});
    std::size_t used = 0;
    for (;;) {
        if (used == bytes.size()) bytes.resize(bytes.size() * 2);
        const ssize_t n = ::read(file.fd, bytes.data() + used, bytes.size() - used);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail(path, errno);
        if (n == 0) break;
        used += static_cast<std::size_t>(n);
    }
    bytes.resize(used);
    return bytes;
}

}  // namespace tubemesh::io
