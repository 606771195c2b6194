#include "job/process_memory.hpp"

#include <malloc.h>

namespace tubemesh::job {

void return_large_blocks_when_freed() { mallopt(M_MMAP_THRESHOLD, 1 << 20); }

void return_free_memory() { malloc_trim(0); }

}  // namespace tubemesh::job
