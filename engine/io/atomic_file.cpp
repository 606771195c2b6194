#include "engine/io/atomic_file.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <memory>
#include <system_error>
#include <utility>

#include "engine/core/types.hpp"

namespace tubemesh::io {

namespace {

// Large enough that the system call count stays small for million-element meshes.
constexpr std::size_t kBufferSize = std::size_t{1} << 20;

// Distinguishes temporaries of concurrent writers in one process; the pid those of others.
std::atomic<unsigned> temporary_counter{0};

constexpr std::string_view kTemporaryMark = ".tmp-";

// The pid in a name temporary_path() made for a target called `name` (any name when empty),
// or 0 for any other name.
long temporary_owner(std::string_view file, std::string_view name) {
    if (file.size() < 2 || file.front() != '.') return 0;
    std::size_t mark = file.rfind(kTemporaryMark);
    if (!name.empty()) {
        if (!file.substr(1).starts_with(name)) return 0;
        mark = name.size() + 1;
        if (!file.substr(mark).starts_with(kTemporaryMark)) return 0;
    }
    if (mark == std::string_view::npos || mark < 2) return 0;
    const std::string_view tail = file.substr(mark + kTemporaryMark.size());  // <pid>-<n>
    long pid = 0;
    const auto [end, error] = std::from_chars(tail.data(), tail.data() + tail.size(), pid);
    if (error != std::errc() || pid <= 0 || end == tail.data() + tail.size() || *end != '-') return 0;
    const std::string_view count = tail.substr(static_cast<std::size_t>(end - tail.data()) + 1);
    if (count.empty() || count.find_first_not_of("0123456789") != std::string_view::npos) return 0;
    return pid;
}

bool alive(long pid) { return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM; }

std::string reason(int error_number) { return std::generic_category().message(error_number); }

thread_local CommitGroup* current_group = nullptr;

}  // namespace

std::filesystem::path temporary_path(const std::filesystem::path& target) {
    std::string name = ".";
    name += target.filename().string();
    name += kTemporaryMark;
    name += std::to_string(::getpid());
    name += '-';
    name += std::to_string(temporary_counter.fetch_add(1));
    return target.parent_path() / name;
}

void remove_dead_temporaries(const std::filesystem::path& folder, const std::string& name) {
    // readdir, not std::filesystem: every file written scans its folder, which may hold a batch's
    // tens of thousands of files (a path object per entry made the scan several times slower).
    const std::filesystem::path dir = folder.empty() ? "." : folder;
    struct Close {
        void operator()(DIR* d) const { ::closedir(d); }
    };
    const std::unique_ptr<DIR, Close> listing(::opendir(dir.c_str()));
    if (!listing) return;
    std::vector<std::string> dead;
    while (const dirent* e = ::readdir(listing.get())) {
        const long pid = e->d_name[0] == '.' ? temporary_owner(e->d_name, name) : 0;
        if (pid > 0 && !alive(pid)) dead.emplace_back(e->d_name);
    }
    for (const std::string& d : dead) {
        std::error_code ignored;
        std::filesystem::remove_all(dir / d, ignored);
    }
}

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
    if (target_.filename().empty()) throw Error("cannot write '" + target_.string() + "': the path names no file");
    remove_dead_temporaries(target_.parent_path(), target_.filename().string());
    // O_EXCL: never reuse a name someone else is writing; 0666 lets the umask decide the
    // final permissions, as for any other file the user creates.
    // Tracked before it exists, so that a signal right after the open still finds it; the
    // name holds our pid, so what an interrupt could unlink there is ours or a dead run's.
    int open_error = 0;
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
        temporary_ = temporary_path(target_);
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
    for (auto f = folders_.rbegin(); f != folders_.rend(); ++f) ::rmdir(f->path.c_str());  // only if empty
}

void CommitGroup::folder_made(const std::filesystem::path& folder) {
    if (current_group) current_group->folders_.push_back({folder, TrackedTemporary(folder, TemporaryKind::Folder)});
}

void CommitGroup::retire(const std::filesystem::path& file) {
    if (current_group)
        current_group->retired_.push_back(file);
    else
        ::unlink(file.c_str());
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
    for (const std::filesystem::path& f : retired_) ::unlink(f.c_str());
    retired_.clear();
}

AtomicFolder::AtomicFolder(std::filesystem::path target) : target_(std::move(target)) {
    namespace fs = std::filesystem;
    if (target_.filename().empty()) target_ = target_.parent_path();  // "dam/" names "dam"
    if (target_.filename().empty() || target_.filename() == "." || target_.filename() == "..")
        throw Error("cannot write the folder '" + target_.string() + "': give it a name");
    std::error_code ec;
    if (fs::exists(target_, ec)) {
        if (!fs::is_directory(target_, ec))
            throw Error("cannot write the folder '" + target_.string() + "': a file of that name is in the way");
        if (!fs::is_empty(target_, ec) || ec)
            throw Error("cannot write the folder '" + target_.string() +
                        "': it already holds files; give a new or empty folder");
    }
    try {
        std::vector<fs::path> missing;
        for (fs::path p = target_.parent_path(); !p.empty() && !fs::exists(p, ec); p = p.parent_path())
            missing.push_back(p);
        // Tracked before they are made, so that an interrupt right after finds them.
        for (auto p = missing.rbegin(); p != missing.rend(); ++p) {
            tracked_.emplace_back(*p, TemporaryKind::Folder);
            if (!fs::create_directory(*p, ec) && ec)
                throw Error("cannot write the folder '" + target_.string() + "': cannot create '" + p->string() +
                            "': " + ec.message());
            made_parents_.push_back(*p);
        }
        remove_dead_temporaries(target_.parent_path(), target_.filename().string());
        staging_ = temporary_path(target_);
        tracked_.emplace_back(staging_, TemporaryKind::FolderAndFiles);
        if (!fs::create_directory(staging_, ec))
            throw Error("cannot write the folder '" + target_.string() + "': cannot create a folder in '" +
                        (target_.has_parent_path() ? target_.parent_path() : fs::path(".")).string() +
                        "': " + (ec ? ec.message() : std::string("it exists")));
    } catch (...) {
        staging_.clear();
        discard();
        throw;
    }
}

AtomicFolder::~AtomicFolder() {
    if (!committed_) discard();
}

void AtomicFolder::commit() {
    if (std::rename(staging_.c_str(), target_.c_str()) != 0)
        throw Error("cannot write the folder '" + target_.string() + "': " + reason(errno));
    committed_ = true;
    tracked_.clear();
}

std::string AtomicFolder::final_names(std::string text) const {
    const std::string from = staging_.string(), to = target_.string();
    if (from.empty()) return text;
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

void AtomicFolder::discard() noexcept {
    std::error_code ignored;
    if (!staging_.empty()) std::filesystem::remove_all(staging_, ignored);
    for (auto p = made_parents_.rbegin(); p != made_parents_.rend(); ++p) ::rmdir(p->c_str());
    tracked_.clear();
}

}  // namespace tubemesh::io
