#pragma once
// One batch at a time per catalogue: a second `tubemesh batch` on the same output folder (and
// shard) would mesh the same blocks twice. An advisory lock on "<catalogue>.lock", released by
// the system when the holder exits or is killed.
#include <filesystem>

namespace tubemesh::batch {

class RunLock {
public:
    // Throws tubemesh::Error when another process holds the lock.
    explicit RunLock(const std::filesystem::path& catalogue);
    ~RunLock();
    RunLock(const RunLock&) = delete;
    RunLock& operator=(const RunLock&) = delete;

private:
    int fd_ = -1;
};

}  // namespace tubemesh::batch
