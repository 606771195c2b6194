#pragma once
// The tetrahedron store of the Delaunay kernel: struct of arrays, 32 bytes per slot.
//
//   vertex[4t + i]     vertex i of tet t (tet 0-1-2 counter-clockwise seen from 3, so
//                      orient3d(v0, v1, v2, v3) > 0; the convention of mesh/topology.hpp)
//   neighbour[4t + i]  the tet across face i (face i is opposite vertex i), encoded as
//                      4 * tet + face-index-in-that-tet, or kNoAdjacent
//
// No flag array: inside the kernel a slot's state lives in its vertex row (see the marks
// below), so visiting a tet touches two cache lines, not three.
//
// Arrays are raw blocks (PodArray: malloc's when small, mappings of their own when large),
// not std::vector: growing a 200 MB block then costs an mremap instead of a copy, and slots
// are never value-initialised (a page is touched only when a tet is written into it), which
// keeps the peak resident size at what is used.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <span>
#include <type_traits>
#include <utility>

#include <tbb/parallel_for.h>


#include "engine/core/types.hpp"
#include "engine/delaunay/huge_pages.hpp"

namespace tubemesh::delaunay {

// "No tet across this face": the face is on the convex hull (in a finished triangulation).
inline constexpr index_t kNoAdjacent = kNoIndex;

// Kernel-only marks, never in a finished result. Vertex ids stay below kInfiniteVertex, so
// the top bit of a vertex id is free.
// The vertex at infinity of the ghost tets that close the convex hull.
inline constexpr index_t kInfiniteVertex = kNoIndex >> 1;
// Set on vertex[4t] while tet t is in the cavity being built.
inline constexpr index_t kCavityMark = ~(kNoIndex >> 1);
// vertex[4t] of a slot on a free list.
inline constexpr index_t kFreeSlot = kNoIndex;

// Largest tet count the 4*tet+face encoding can address.
inline constexpr std::size_t kMaxTets = (std::size_t{1} << 30) - 1;

// A growable, uninitialised array of trivially copyable T. From kMappedBlockBytes on it is a
// mapping of its own (huge_pages.hpp), which grows without a copy: the tet store grows every
// refinement round and every flip round, and a copy of it set the tet step's memory peak.
template <class T>
class PodArray {
    static_assert(std::is_trivially_copyable_v<T>);

public:
    PodArray() = default;
    PodArray(const PodArray&) = delete;
    PodArray& operator=(const PodArray&) = delete;
    PodArray(PodArray&& o) noexcept
        : data_(std::exchange(o.data_, nullptr)),
          cap_(std::exchange(o.cap_, 0)),
          mapped_(std::exchange(o.mapped_, false)) {}
    PodArray& operator=(PodArray&& o) noexcept {
        if (this != &o) {
            release();
            data_ = std::exchange(o.data_, nullptr);
            cap_ = std::exchange(o.cap_, 0);
            mapped_ = std::exchange(o.mapped_, false);
        }
        return *this;
    }
    ~PodArray() { release(); }

    // Grows or shrinks to exactly n elements, keeping the first min(n, old) elements.
    void reallocate(std::size_t n) {
        if (n == cap_) return;
        if (n == 0) {
            release();
            return;
        }
        const std::size_t bytes = n * sizeof(T);
        void* p = nullptr;
        if (mapped_) {
            p = remap_block(data_, cap_ * sizeof(T), bytes);
        } else if (kMapsBlocks && bytes >= kMappedBlockBytes) {
            p = map_block(bytes);
            if (p && data_) {
                std::memcpy(p, data_, std::min(cap_, n) * sizeof(T));
                std::free(data_);
            }
        } else {
            p = std::realloc(data_, bytes);
        }
        if (!p) throw std::bad_alloc();
        mapped_ = mapped_ || (kMapsBlocks && bytes >= kMappedBlockBytes);
        data_ = static_cast<T*>(p);
        cap_ = n;
    }

    T* data() { return data_; }
    const T* data() const { return data_; }
    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    std::size_t capacity() const { return cap_; }

private:
    void release() {
        if (mapped_) unmap_block(data_, cap_ * sizeof(T));
        else std::free(data_);
        data_ = nullptr;
        cap_ = 0;
        mapped_ = false;
    }

    T* data_ = nullptr;
    std::size_t cap_ = 0;
    bool mapped_ = false;  // data_ is a mapping (map_block), else malloc's
};

class TetStore {
public:
    // Slots in use (live tets, and inside the kernel also free and ghost slots).
    index_t size() const { return size_; }
    index_t capacity() const { return static_cast<index_t>(vertex_.capacity() / 4); }
    // Bytes held by the arrays (capacity, not size).
    std::size_t bytes() const { return (vertex_.capacity() + neighbour_.capacity()) * sizeof(index_t); }
    static constexpr std::size_t kBytesPerSlot = 8 * sizeof(index_t);

    std::span<const index_t> vertices() const { return {vertex_.data(), std::size_t{4} * size_}; }
    std::span<const index_t> neighbours() const { return {neighbour_.data(), std::size_t{4} * size_}; }

    index_t* vertex(index_t t) { return vertex_.data() + std::size_t{4} * t; }
    const index_t* vertex(index_t t) const { return vertex_.data() + std::size_t{4} * t; }
    index_t& neighbour(index_t face_code) { return neighbour_[face_code]; }
    index_t neighbour(index_t face_code) const { return neighbour_[face_code]; }

    // A copy of the slots in use. The store has no copy constructor, so that a 100 MB copy is
    // always asked for by name.
    TetStore clone() const;

    // Capacity changes only between parallel phases: pointers into the arrays move.
    void reserve(std::size_t n);
    void shrink_to_fit() { set_capacity(size_); }
    // New slots above size() are uninitialised.
    void set_size(index_t n) { size_ = n; }

private:
    void set_capacity(std::size_t n);

    PodArray<index_t> vertex_;
    PodArray<index_t> neighbour_;
    index_t size_ = 0;
};

inline void TetStore::reserve(std::size_t n) {
    if (n > kMaxTets) throw Error("Delaunay: more than 2^30 tetrahedra do not fit the 32-bit adjacency encoding");
    if (n > capacity()) set_capacity(n);
}

inline TetStore TetStore::clone() const {
    TetStore c;
    c.reserve(size_);
    c.size_ = size_;
    // In blocks, in parallel: the copy's pages are first touched by every thread, not one.
    constexpr std::size_t kBlock = std::size_t{1} << 16;
    const std::size_t n = std::size_t{4} * size_;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kBlock), [&](const tbb::blocked_range<std::size_t>& r) {
        const std::size_t bytes = (r.end() - r.begin()) * sizeof(index_t);
        std::memcpy(c.vertex_.data() + r.begin(), vertex_.data() + r.begin(), bytes);
        std::memcpy(c.neighbour_.data() + r.begin(), neighbour_.data() + r.begin(), bytes);
    });
    return c;
}

inline void TetStore::set_capacity(std::size_t n) {
    vertex_.reallocate(4 * n);
    neighbour_.reallocate(4 * n);
}

}  // namespace tubemesh::delaunay
