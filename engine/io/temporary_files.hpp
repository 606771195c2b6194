#pragma once
// The temporary files and folders this process is writing, so that an interrupt removes them and
// nothing else. A signal handler may only call async-signal-safe functions, so the paths live in
// a fixed table of slots (a path that does not fit is simply not tracked) and removal is unlink()
// and rmdir().
#include <filesystem>

namespace tubemesh::io {

// On an interrupt the tracked files go first, then the folders, each once it is empty.
enum class TemporaryKind {
    File,
    Folder,          // removed only if empty: safe to track before it is made
    FolderAndFiles,  // the files directly inside go too: only for a folder this process made
};

// Tracks a temporary for as long as it lives; release() stops tracking it (renamed or removed).
class TrackedTemporary {
public:
    TrackedTemporary() = default;
    explicit TrackedTemporary(const std::filesystem::path& path, TemporaryKind kind = TemporaryKind::File);
    ~TrackedTemporary() { release(); }
    TrackedTemporary(TrackedTemporary&& other) noexcept;
    TrackedTemporary& operator=(TrackedTemporary&& other) noexcept;
    TrackedTemporary(const TrackedTemporary&) = delete;
    TrackedTemporary& operator=(const TrackedTemporary&) = delete;

    void release() noexcept;

private:
    int slot_ = -1;
};

// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove every tracked temporary and then
// end the process by the same signal (so the exit status still names it). For programs, not
// libraries: it replaces whatever handlers were there.
void remove_temporaries_on_signals();

}  // namespace tubemesh::io
