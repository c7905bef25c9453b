#include "candela/distributed/mpi_channel.h"

#include <climits>
#include <stdexcept>

namespace candela {

MpiChannel::~MpiChannel() { wait_all(); }

void MpiChannel::send(int rank, int tag, std::vector<unsigned char> bytes) {
    if (bytes.size() > size_t(INT_MAX)) throw std::runtime_error("MPI message over 2 GiB");
    bytes_sent_ += bytes.size();
    Pending& p = pending_.emplace_back(Pending{MPI_REQUEST_NULL, std::move(bytes)});
    MPI_Isend(p.bytes.data(), int(p.bytes.size()), MPI_BYTE, rank, tag, MPI_COMM_WORLD, &p.request);
}

std::optional<ReceivedMessage> MpiChannel::try_receive(int tag) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &flag, &status);
    if (!flag) return std::nullopt;
    int count = 0;
    MPI_Get_count(&status, MPI_BYTE, &count);
    ReceivedMessage m{status.MPI_SOURCE, std::vector<unsigned char>(size_t(count))};
    bytes_received_ += size_t(count);
    MPI_Recv(m.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return m;
}

void MpiChannel::progress() {
    for (auto it = pending_.begin(); it != pending_.end();) {
        int done = 0;
        MPI_Test(&it->request, &done, MPI_STATUS_IGNORE);
        it = done ? pending_.erase(it) : std::next(it);
    }
}

void MpiChannel::wait_all() {
    for (Pending& p : pending_) MPI_Wait(&p.request, MPI_STATUS_IGNORE);
    pending_.clear();
}

}  // namespace candela
