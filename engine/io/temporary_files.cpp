#include "engine/io/temporary_files.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <utility>

namespace tubemesh::io {

namespace {

// More than any run writes at once (one per output and the report).
constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;

struct Slot {
    std::atomic<bool> taken{false};  // owned by a TrackedTemporary
    std::atomic<bool> live{false};   // path is complete and may be removed
    std::atomic<TemporaryKind> kind{TemporaryKind::File};
    char path[kPathBytes];
};

std::array<Slot, kSlots> slots;
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<TemporaryKind>::is_always_lock_free,
              "the signal handler reads the slots' flags");

// The head of a record the getdents64 system call fills (glibc's readdir is not
// async-signal-safe); the name follows d_type.
struct LinuxDirent64 {
    std::uint64_t d_ino;
    std::int64_t d_off;
    unsigned short d_reclen;
    unsigned char d_type;
};
constexpr std::size_t kNameOffset = offsetof(LinuxDirent64, d_type) + 1;

// Unlinks the files directly inside `path`; async-signal-safe. Reads the folder again after a
// pass that removed something, since removing while reading may skip entries.
void empty_folder(const char* path) {
    const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    alignas(LinuxDirent64) char buffer[4096];
    for (bool removed = true; removed;) {
        removed = false;
        ::lseek(fd, 0, SEEK_SET);
        for (;;) {
            const long n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer);
            if (n <= 0) break;
            for (long at = 0; at < n;) {
                const auto* e = reinterpret_cast<const LinuxDirent64*>(buffer + at);
                at += e->d_reclen;
                if (e->d_type == DT_DIR) continue;  // ".", ".." and subfolders
                removed = ::unlinkat(fd, reinterpret_cast<const char*>(e) + kNameOffset, 0) == 0 || removed;
            }
        }
    }
    ::close(fd);
}

// The slot's kind when it holds a path to remove.
std::optional<TemporaryKind> live_kind(const Slot& s) {
    if (!s.live.load(std::memory_order_acquire)) return std::nullopt;
    return s.kind.load(std::memory_order_relaxed);
}

void remove_all_tracked(int signal_number) {
    for (Slot& s : slots)
        if (live_kind(s) == TemporaryKind::File) ::unlink(s.path);
    for (Slot& s : slots)
        if (live_kind(s) == TemporaryKind::FolderAndFiles) empty_folder(s.path);
    // A folder goes once the folders inside it are gone: repeat while some rmdir succeeds.
    for (bool removed = true; removed;) {
        removed = false;
        for (Slot& s : slots)
            if (live_kind(s).value_or(TemporaryKind::File) != TemporaryKind::File && ::rmdir(s.path) == 0) {
                s.live.store(false, std::memory_order_relaxed);
                removed = true;
            }
    }
    // SA_RESETHAND restored the default action; it ends the process once the handler returns.
    ::raise(signal_number);
}

}  // namespace

TrackedTemporary::TrackedTemporary(const std::filesystem::path& path, TemporaryKind kind) {
    const std::string& text = path.native();
    if (text.size() >= kPathBytes) return;
    for (int i = 0; i < kSlots; ++i) {
        bool expected = false;
        if (!slots[i].taken.compare_exchange_strong(expected, true)) continue;
        std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
        slots[i].kind.store(kind, std::memory_order_relaxed);
        slots[i].live.store(true, std::memory_order_release);
        slot_ = i;
        return;
    }
}

TrackedTemporary::TrackedTemporary(TrackedTemporary&& other) noexcept : slot_(std::exchange(other.slot_, -1)) {}

TrackedTemporary& TrackedTemporary::operator=(TrackedTemporary&& other) noexcept {
    if (this != &other) {
        release();
        slot_ = std::exchange(other.slot_, -1);
    }
    return *this;
}

void TrackedTemporary::release() noexcept {
    if (slot_ < 0) return;
    slots[slot_].live.store(false, std::memory_order_release);
    slots[slot_].taken.store(false, std::memory_order_release);
    slot_ = -1;
}

void remove_temporaries_on_signals() {
    struct sigaction action {};
    action.sa_handler = remove_all_tracked;
    constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
    sigemptyset(&action.sa_mask);
    for (int s : kSignals) sigaddset(&action.sa_mask, s);
    action.sa_flags = SA_RESETHAND;
    for (int s : kSignals) sigaction(s, &action, nullptr);
}

}  // namespace tubemesh::io
