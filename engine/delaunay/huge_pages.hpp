#pragma once
// Transparent huge pages for the kernel's large, randomly accessed blocks, and blocks that are
// mappings of their own, which grow without a copy.
#include <cstddef>
#include <cstdint>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace tubemesh::delaunay {

// Blocks of at least this many bytes are worth 2 MB pages.
inline constexpr std::size_t kHugeBlockBytes = std::size_t{4} << 21;

// Asks the kernel to back a large block with 2 MB pages where it can (Linux transparent huge
// pages in "madvise" mode, the default here). The kernel's walks and cavities jump across
// a store of hundreds of MB: with 4 KB pages nearly every tet visited misses the TLB, and
// two threads contend in the page walker. A no-op elsewhere and for small blocks.
// Only the block's 2 MB-aligned middle is advised, which splits a block malloc mapped in three:
// not for blocks that grow with realloc (its mremap then refuses the block and copies it).
inline void advise_huge_pages(void* data, std::size_t bytes) {
#ifdef __linux__
    constexpr std::uintptr_t kHuge = std::uintptr_t{1} << 21;
    if (bytes < kHugeBlockBytes) return;
    const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice: failure is harmless
#else
    (void)data;
    (void)bytes;
#endif
}

// Blocks of at least kMappedBlockBytes as anonymous mappings of their own (Linux; elsewhere
// there are none and callers use malloc). A mapping grows and shrinks with mremap, which moves
// page tables and copies no page: the old and the new block are never both resident, as they
// are while realloc copies a block out of malloc's arenas. From kHugeBlockBytes on the whole
// mapping is advised to huge pages, so it stays one mapping that mremap takes.
#ifdef __linux__
inline constexpr bool kMapsBlocks = true;
#else
inline constexpr bool kMapsBlocks = false;
#endif
inline constexpr std::size_t kMappedBlockBytes = std::size_t{1} << 20;

// The bytes a mapping of `bytes` takes: whole 4 KB pages.
inline std::size_t mapped_size(std::size_t bytes) { return (bytes + 4095) & ~std::size_t{4095}; }

inline void advise_mapped_block(void* p, std::size_t bytes) {
#ifdef __linux__
    if (bytes >= kHugeBlockBytes) madvise(p, mapped_size(bytes), MADV_HUGEPAGE);  // advice: failure is harmless
#else
    (void)p;
    (void)bytes;
#endif
}

// A new mapping of at least `bytes` (zero pages), or nullptr when there is no room.
inline void* map_block(std::size_t bytes) {
#ifdef __linux__
    void* p = mmap(nullptr, mapped_size(bytes), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) return nullptr;
    advise_mapped_block(p, bytes);
    return p;
#else
    (void)bytes;
    return nullptr;
#endif
}

// The mapping p of old_bytes resized to new_bytes, its first min(old, new) bytes kept (it may
// move), or nullptr when there is no room (p is then unchanged).
inline void* remap_block(void* p, std::size_t old_bytes, std::size_t new_bytes) {
#ifdef __linux__
    void* q = mremap(p, mapped_size(old_bytes), mapped_size(new_bytes), MREMAP_MAYMOVE);
    if (q == MAP_FAILED) return nullptr;
    advise_mapped_block(q, new_bytes);
    return q;
#else
    (void)p;
    (void)old_bytes;
    (void)new_bytes;
    return nullptr;
#endif
}

inline void unmap_block(void* p, std::size_t bytes) {
#ifdef __linux__
    munmap(p, mapped_size(bytes));
#else
    (void)p;
    (void)bytes;
#endif
}

}  // namespace tubemesh::delaunay
