#include "tools/mpi/mpi_messages.hpp"

#include <time.h>

#include <vector>

namespace tubemesh::mpi {

void send_json(const nlohmann::json& message, int to, int tag) {
    const std::string text = message.is_null() ? std::string() : message.dump();
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

std::optional<Received> try_receive(int tag) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &flag, &status);
    if (!flag) return std::nullopt;
    int size = 0;
    MPI_Get_count(&status, MPI_CHAR, &size);
    std::vector<char> text(static_cast<std::size_t>(size));
    MPI_Recv(text.data(), size, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    Received r;
    r.from = status.MPI_SOURCE;
    r.tag = status.MPI_TAG;
    if (size > 0) r.message = nlohmann::json::parse(text.begin(), text.end());
    return r;
}

Received receive_any() {
    const timespec pause{0, 5'000'000};  // 5 ms between looks: nothing next to a block's seconds
    for (;;) {
        if (auto r = try_receive(MPI_ANY_TAG)) return std::move(*r);
        nanosleep(&pause, nullptr);
    }
}

}  // namespace tubemesh::mpi
