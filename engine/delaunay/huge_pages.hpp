#pragma once
// Transparent huge pages for the kernel's large, randomly accessed blocks.
#include <cstddef>
#include <cstdint>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace tubemesh::delaunay {

// Asks the kernel to back a large block with 2 MB pages where it can (Linux transparent huge
// pages in "madvise" mode, the default here). The kernel's walks and cavities jump across
// a store of hundreds of MB: with 4 KB pages nearly every tet visited misses the TLB, and
// two threads contend in the page walker. A no-op elsewhere and for small blocks.
inline void advise_huge_pages(void* data, std::size_t bytes) {
#ifdef __linux__
    constexpr std::uintptr_t kHuge = std::uintptr_t{1} << 21;
    if (bytes < 4 * kHuge) return;
    const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // advice: failure is harmless
#else
    (void)data;
    (void)bytes;
#endif
}

}  // namespace tubemesh::delaunay
