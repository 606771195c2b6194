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

thread_local CommitGroup* current_group = nullptr;

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
    if (target_.filename().empty()) throw Error("cannot write '" + target_.string() + "': the path names no file");
    // O_EXCL: never reuse a name someone else is writing; 0666 lets the umask decide the
    // final permissions, as for any other file the user creates.
    // Tracked before it exists, so that a signal right after the open still finds it; the
    // name holds our pid, so what an interrupt could unlink there is ours or a dead run's.
    int open_error = 0;
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
        temporary_ = temporary_name(target_);
        tracked_ = TrackedTemporary(temporary_);
        fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        open_error = errno;
        if (fd_ < 0) tracked_.release();
        if (fd_ < 0 && open_error != EEXIST) break;
    }
    if (fd_ < 0) {
        const int error_number = open_error;
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
    if (current_group) {
        current_group->pending_.push_back({std::exchange(temporary_, {}), target_, std::move(tracked_)});
        return;
    }
    if (std::rename(temporary_.c_str(), target_.c_str()) != 0) fail("cannot replace", errno);
    temporary_.clear();
    tracked_.release();
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
    tracked_.release();
}

CommitGroup::CommitGroup() : outer_(std::exchange(current_group, this)) {}

CommitGroup::~CommitGroup() {
    current_group = outer_;
    for (Pending& p : pending_) ::unlink(p.temporary.c_str());
    for (auto f = folders_.rbegin(); f != folders_.rend(); ++f) ::rmdir(f->c_str());  // only if empty
}

void CommitGroup::folder_made(const std::filesystem::path& folder) {
    if (current_group) current_group->folders_.push_back(folder);
}

void CommitGroup::commit() {
    // Only renames within the targets' folders are left: the writing, where a full disk or an
    // interrupt strikes, is over for every file before the first target changes.
    for (std::size_t i = 0; i < pending_.size(); ++i) {
        if (std::rename(pending_[i].temporary.c_str(), pending_[i].target.c_str()) != 0) {
            const int error_number = errno;
            const std::string target = pending_[i].target.string();
            pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(i));
            throw Error("cannot replace '" + target + "': " + reason(error_number));
        }
        pending_[i].tracked.release();
    }
    pending_.clear();
    folders_.clear();
}

}  // namespace tubemesh::io
