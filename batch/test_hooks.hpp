#pragma once
// Test-only fault injection, so the tests drive kill -9, crashes and hangs at exact moments
// instead of sleeping and hoping. Inert unless TUBEMESH_BATCH_TEST_FAULT is set to
// "MOMENT:ARG":
//   in the batch process (ARG = N: at the N-th time the moment comes, from 1)
//     plan       the catalogue holds the plan, no block started
//     commit     inside a block's catalogue transaction, before it commits
//     recorded   after a block's row committed
//   in a block's worker (ARG = the block id)
//     start      before meshing: the worker kills its batch process, then itself
//     written    after the block's files are written, before the batch process knows
//     crash      the worker dies of SIGSEGV (a library fault)
//     hang       the worker never returns (the time limit must end it)
//     die-once   the worker is killed on the block's first attempt only
#include <string_view>

namespace tubemesh::batch {

void fault_point(std::string_view moment);
void worker_fault_point(std::string_view moment, std::string_view block_id, int attempt);

}  // namespace tubemesh::batch
