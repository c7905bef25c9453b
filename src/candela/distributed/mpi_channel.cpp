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
    while (true) {  // match (and start receiving) everything that has arrived
        int flag = 0;
        MPI_Message message;
        MPI_Status status;
        MPI_Improbe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &flag, &message, &status);
        if (!flag) break;
        int count = 0;
        MPI_Get_count(&status, MPI_BYTE, &count);
        Incoming& in = incoming_.emplace_back(Incoming{MPI_REQUEST_NULL, status.MPI_SOURCE, {}});
        in.bytes.resize(size_t(count));
        MPI_Imrecv(in.bytes.data(), count, MPI_BYTE, &message, &in.request);
    }
    if (incoming_.empty()) return std::nullopt;
    int done = 0;
    MPI_Test(&incoming_.front().request, &done, MPI_STATUS_IGNORE);
    if (!done) return std::nullopt;
    ReceivedMessage m{incoming_.front().source, std::move(incoming_.front().bytes)};
    incoming_.pop_front();
    bytes_received_ += m.bytes.size();
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
    for (Incoming& in : incoming_) MPI_Wait(&in.request, MPI_STATUS_IGNORE);
    incoming_.clear();
}

}  // namespace candela
