#pragma once
// An output file that appears under its final name complete or not at all.
//
// Bytes go to a temporary file beside the target (same directory, so the final rename never
// crosses a file system and is atomic); commit() flushes, syncs and renames it over the
// target. Destroying an uncommitted AtomicFile - an exception while writing, a failed
// commit - removes the temporary, so a failure never leaves a partial mesh behind.
// Every error is a tubemesh::Error naming the target path and the system's reason.
// The temporary is tracked (engine/io/temporary_files.hpp), so an interrupt removes it too.
#include <bit>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "engine/io/temporary_files.hpp"

namespace tubemesh::io {

// Binary mesh formats are written little-endian, byte for byte as they sit in memory.
static_assert(std::endian::native == std::endian::little, "tubemesh writes binary files on little-endian hosts only");

class AtomicFile {
public:
    explicit AtomicFile(std::filesystem::path target);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    void write(std::string_view text) { write_bytes(text.data(), text.size()); }
    void write_bytes(const void* data, std::size_t size);

    // A value's bytes as they are in memory (binary formats).
    template <class T>
    void write_raw(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        write_bytes(&value, sizeof(T));
    }

    // Decimal text; doubles in the shortest form that reads back to the same bits, so an
    // ASCII round trip is exact.
    template <class T>
    void write_number(T value) {
        char text[32];
        const auto result = std::to_chars(text, text + sizeof text, value);
        write_bytes(text, static_cast<std::size_t>(result.ptr - text));
    }

    // Flushes, syncs and renames over the target (inside a CommitGroup: leaves the rename to
    // the group). Nothing may be written afterwards.
    void commit();

    const std::filesystem::path& target() const { return target_; }

private:
    void flush();
    [[noreturn]] void fail(const char* action, int error_number);
    void discard() noexcept;

    std::filesystem::path target_;
    std::filesystem::path temporary_;
    TrackedTemporary tracked_;
    int fd_ = -1;
    std::vector<char> buffer_;
    std::size_t used_ = 0;
};

// Several outputs that appear all or none: while a group lives, AtomicFile::commit() on the
// same thread completes each file under its temporary name, and the group's commit() renames
// them all. Destroying the group first removes the temporaries, so a run that fails at its
// third file leaves the first two targets as they were, including files that existed before.
class CommitGroup {
public:
    CommitGroup();
    ~CommitGroup();
    CommitGroup(const CommitGroup&) = delete;
    CommitGroup& operator=(const CommitGroup&) = delete;

    void commit();

    // A folder a writer made for its files (the .vtm's blocks): the current group, if any,
    // removes it again when it is destroyed uncommitted and the folder is empty.
    static void folder_made(const std::filesystem::path& folder);

private:
    friend class AtomicFile;
    struct Pending {
        std::filesystem::path temporary, target;
        TrackedTemporary tracked;
    };
    std::vector<Pending> pending_;
    std::vector<std::filesystem::path> folders_;
    CommitGroup* outer_;
};

}  // namespace tubemesh::io
