#pragma once
// A ceiling on the process's memory, so that a run that outgrows the machine ends with an
// error the user can act on instead of the kernel's out-of-memory killer (exit 137, no word).
// The ceiling is on the address space (RLIMIT_AS): an allocation past it fails with
// std::bad_alloc, which the mesh command turns into a tubemesh::Error.
namespace tubemesh::cli {

// Lowers the soft address-space limit to `bytes` (never raises it). Returns the limit now in
// force in bytes, or 0 when there is none.
double limit_memory(double bytes);

}  // namespace tubemesh::cli
