#pragma once
// How a meshing process gives memory back. glibc serves a freed large block's next request
// from the heap once its mmap threshold has risen past it (it adapts upwards on every free of
// an mmapped block), so the temporaries of one phase stay resident under the next phase's:
// the resident peak of a run then counts them twice. Fixing the threshold at 1 MiB makes every
// large block its own mapping, returned to the system when freed.
namespace tubemesh::job {

// For a program's main, before any work: the whole process is affected.
void return_large_blocks_when_freed();

// Gives the free pages inside the allocator's heaps back to the system: after a phase that
// freed many small blocks from several threads (the tet step's plans, stars and scratch), so
// that the next phase's peak does not stand on them. A few milliseconds.
void return_free_memory();

}  // namespace tubemesh::job
