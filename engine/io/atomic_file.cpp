#include "engine/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <system_error>
#include <utility>

#include "engine/core/types.hpp"

namespace tubemesh::io {

namespace {

// Large enough that the system call count stays small for million-element meshes.
constexpr std::size_t kBufferSize = std::size_t{1} << 20;

// Distinguishes temporaries of concurrent writers in one process; the pid those of others.
std::atomic<unsigned> temporary_counter{0};

std::filesystem::path temporary_name(const std::filesystem::path& target) {
    std::string name = ".";
    name += target.filename().string();
    name += ".tmp-";
    name += std::to_string(::getpid());
    name += '-';
    name += std::to_string(temporary_counter.fetch_add(1));
    return target.parent_path() / name;
}

std::string reason(int error_number) { return std::generic_category().message(error_number); }

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
    if (target_.filename().empty()) throw Error("cannot write '" + target_.string() + "': the path names no file");
    // O_EXCL: never reuse a name someone else is writing; 0666 lets the umask decide the
    // final permissions, as for any other file the user creates.
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
        temporary_ = temporary_name(target_);
        fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd_ < 0 && errno != EEXIST) break;
    }
    if (fd_ < 0) {
        const int error_number = errno;
        temporary_.clear();
        const std::filesystem::path dir = target_.has_parent_path() ? target_.parent_path() : ".";
        throw Error("cannot write '" + target_.string() + "': cannot create a file in '" + dir.string() +
                    "': " + reason(error_number));
    }
    buffer_.resize(kBufferSize);
}

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::write_bytes(const void* data, std::size_t size) {
    if (fd_ < 0) throw Error("internal error: writing to '" + target_.string() + "' after it was closed");
    if (used_ + size > buffer_.size()) flush();
    if (size >= buffer_.size()) {
        // Too big to buffer: write through (the buffer is empty after flush()).
        const char* p = static_cast<const char*>(data);
        while (size > 0) {
            const ssize_t n = ::write(fd_, p, size);
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) fail("cannot write", errno);
            p += n;
            size -= static_cast<std::size_t>(n);
        }
        return;
    }
    std::memcpy(buffer_.data() + used_, data, size);
    used_ += size;
}

void AtomicFile::flush() {
    std::size_t done = 0;
    while (done < used_) {
        const ssize_t n = ::write(fd_, buffer_.data() + done, used_ - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail("cannot write", errno);
        done += static_cast<std::size_t>(n);
    }
    used_ = 0;
}

void AtomicFile::commit() {
    flush();
    // fsync before rename: otherwise a crash soon after could leave the final name pointing
    // at an empty file on some file systems, which is the partial mesh we promise not to leave.
    if (::fsync(fd_) != 0) fail("cannot write", errno);
    const int fd = std::exchange(fd_, -1);
    if (::close(fd) != 0) fail("cannot write", errno);
    if (std::rename(temporary_.c_str(), target_.c_str()) != 0) fail("cannot replace", errno);
    temporary_.clear();
}

void AtomicFile::fail(const char* action, int error_number) {
    discard();
    throw Error(std::string(action) + " '" + target_.string() + "': " + reason(error_number));
}

void AtomicFile::discard() noexcept {
    if (fd_ >= 0) ::close(std::exchange(fd_, -1));
    if (!temporary_.empty()) {
        ::unlink(temporary_.c_str());
        temporary_.clear();
    }
}

}  // namespace tubemesh::io
