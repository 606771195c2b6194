#pragma once
// Streaming base64 encoder into an AtomicFile. VTK decodes a binary DataArray as one
// continuous base64 stream (header and data together), so values are fed one by one and
// only finish() pads the end.
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "engine/io/atomic_file.hpp"

namespace tubemesh::io {

class Base64Writer {
public:
    explicit Base64Writer(AtomicFile& out) : out_(out) {}

    void put_bytes(const void* data, std::size_t size);

    template <class T>
    void put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        put_bytes(&value, sizeof(T));
    }

    // Writes the pending bytes with '=' padding; the writer can start a new stream afterwards.
    void finish();

private:
    void encode_pending();

    AtomicFile& out_;
    unsigned char pending_[3] = {0, 0, 0};
    int pending_count_ = 0;
    char text_[4096];  // encoded characters not yet handed to the file
    std::size_t text_used_ = 0;
};

}  // namespace tubemesh::io
