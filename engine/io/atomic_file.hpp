#pragma once
// An output file that appears under its final name complete or not at all.
//
// Bytes go to a temporary file beside the target (same directory, so the final rename never
// crosses a file system and is atomic); commit() flushes, syncs and renames it over the
// target. Destroying an uncommitted AtomicFile - an exception while writing, a failed
// commit - removes the temporary, so a failure never leaves a partial mesh behind.
// Every error is a tubemesh::Error naming the target path and the system's reason.
// The temporary is tracked (engine/io/temporary_files.hpp), so an interrupt removes it too; what
// a kill -9 leaves behind, the next AtomicFile for the same target removes.
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

// A fresh name beside `target` for a temporary of this process: ".<name>.tmp-<pid>-<n>".
std::filesystem::path temporary_path(const std::filesystem::path& target);

// Removes from `folder` the temporaries (files or folders, named as temporary_path() names them)
// of processes that are no longer alive, as a kill -9 leaves them; those of a live process, this
// one included, stay. With `name`, only those of that target's name. Errors are ignored: a
// leftover is not worth failing a run for.
void remove_dead_temporaries(const std::filesystem::path& folder, const std::string& name = {});

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
    // removes it again when it is destroyed uncommitted (or interrupted) and the folder is empty.
    static void folder_made(const std::filesystem::path& folder);

    // A file that the files being written replace (a part of an earlier .vtm that this one does
    // not have): removed once the group has renamed its files into place, at once without a group.
    static void retire(const std::filesystem::path& file);

private:
    friend class AtomicFile;
    struct Pending {
        std::filesystem::path temporary, target;
        TrackedTemporary tracked;
    };
    struct Folder {
        std::filesystem::path path;
        TrackedTemporary tracked;
    };
    std::vector<Pending> pending_;
    std::vector<Folder> folders_;
    std::vector<std::filesystem::path> retired_;
    CommitGroup* outer_;
};

// A folder of files that appears under its final name complete or not at all: the files are
// written into a hidden sibling (temporary_path()), and commit() renames it onto the target. The
// target must not exist yet, or be an empty folder; missing parent folders are made (and removed
// again if nothing is committed). Until commit() an interrupt removes the sibling, as destroying
// an uncommitted AtomicFolder does. Errors are tubemesh::Error naming the folder and the reason.
class AtomicFolder {
public:
    explicit AtomicFolder(std::filesystem::path target);
    ~AtomicFolder();
    AtomicFolder(const AtomicFolder&) = delete;
    AtomicFolder& operator=(const AtomicFolder&) = delete;

    // Where the files go until commit().
    const std::filesystem::path& path() const { return staging_; }
    void commit();

    // `text` (an error message) with path() spelled as the target, the name the user gave.
    std::string final_names(std::string text) const;

private:
    void discard() noexcept;

    std::filesystem::path target_;
    std::filesystem::path staging_;
    std::vector<std::filesystem::path> made_parents_;  // outermost first
    std::vector<TrackedTemporary> tracked_;
    bool committed_ = false;
};

}  // namespace tubemesh::io
