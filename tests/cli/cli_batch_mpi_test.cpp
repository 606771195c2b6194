// `mpirun -np 2 tubemesh-mpi batch` on the small dam: the same files and catalogue as
// `tubemesh batch`, and a worker that dies has its block dealt again. Skipped when the build
// found no MPI (tubemesh-mpi is then not built).
#include <gtest/gtest.h>

#include <string>

#include "tests/cli/batch_runs.hpp"

namespace tubemesh::testing {
namespace {

// Open MPI refuses to start as root without these (CI runs as root); 2 ranks may exceed the
// machine's cores.
std::string mpirun(const std::string& fault = "") {
#ifdef TUBEMESH_MPI
    std::string env = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1";
    if (!fault.empty()) env += " TUBEMESH_BATCH_TEST_FAULT=" + fault;
    return "env " + env + " " + shell_quote(TUBEMESH_MPIEXEC) + " --oversubscribe -np 2 " +
           (fault.empty() ? "" : "-x TUBEMESH_BATCH_TEST_FAULT ") + shell_quote(TUBEMESH_MPI);
#else
    (void)fault;
    return "";
#endif
}

// The small dam and its single-machine run, to compare with.
class CliBatchMpi : public ::testing::Test {
protected:
    void SetUp() override {
#ifndef TUBEMESH_MPI
        GTEST_SKIP() << "tubemesh-mpi was not built: CMake found no MPI (install libopenmpi-dev)";
#endif
        ASSERT_EQ(batch(dam, "single", "").exit_code, 0);
    }
    const SmallDam dam;
};

TEST_F(CliBatchMpi, TwoRanksWriteWhatOneMachineWrites) {
    const ProcessResult r = run_command(mpirun() + " batch " + q(dam.manifest()) + " -o " + q(dam.dir / "mpi"));
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const std::vector<Row> rows = catalogue_rows(dam.dir / "mpi");
    EXPECT_EQ(stable(rows), stable(catalogue_rows(dam.dir / "single")));
    // Both ranks meshed blocks (rank 0 deals and meshes one at a time beside the dealing).
    int on_rank1 = 0;
    for (const Row& row : rows) on_rank1 += row.at("worker").starts_with("rank 1 ");
    EXPECT_GT(on_rank1, 0);
    EXPECT_LT(on_rank1, 4);

    // Resumed under MPI: nothing left to do.
    const ProcessResult again = run_command(mpirun() + " batch " + q(dam.manifest()) + " -o " + q(dam.dir / "mpi"));
    EXPECT_EQ(again.exit_code, 0);
    EXPECT_NE(again.out.find("4 done before, 0 meshed now"), std::string::npos) << again.out;
}

TEST_F(CliBatchMpi, ADeadWorkersBlockIsDealtAgain) {
    const ProcessResult r =
        run_command(mpirun("die-once:c1-l2") + " batch " + q(dam.manifest()) + " -o " + q(dam.dir / "mpi") + " --verbose");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("c1-l2: its worker died, dealt again"), std::string::npos) << r.out;
    EXPECT_EQ(stable(catalogue_rows(dam.dir / "mpi")), stable(catalogue_rows(dam.dir / "single")));
}

}  // namespace
}  // namespace tubemesh::testing
