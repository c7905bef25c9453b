#pragma once
// Point-to-point messages for the MPI renderer, without blocking: sends are MPI_Isend kept until
// complete (two ranks each blocked in a large MPI_Send to the other would wait for ever), and
// receives poll with MPI_Iprobe, so the calling thread can also watch its render threads and
// stop signals. Only the thread that owns the MpiSession uses a channel.
#include <cstdint>
#include <list>
#include <optional>
#include <vector>

#include <mpi.h>

namespace candela {

inline constexpr int kTagToRoot = 1;    // worker -> rank 0
inline constexpr int kTagToWorker = 2;  // rank 0 -> worker

struct ReceivedMessage {
    int source = 0;
    std::vector<unsigned char> bytes;
};

class MpiChannel {
  public:
    MpiChannel() = default;
    MpiChannel(const MpiChannel&) = delete;
    MpiChannel& operator=(const MpiChannel&) = delete;
    ~MpiChannel();  // waits for the sends still in flight

    // Sends the bytes to `rank` under `tag`; returns at once. Counts the bytes.
    void send(int rank, int tag, std::vector<unsigned char> bytes);
    // A message with `tag` from any rank, if one has arrived.
    std::optional<ReceivedMessage> try_receive(int tag);
    // Frees the buffers of completed sends.
    void progress();
    // Waits until every send is complete (the receivers must go on receiving).
    void wait_all();

    uint64_t bytes_sent() const { return bytes_sent_; }
    uint64_t bytes_received() const { return bytes_received_; }

  private:
    struct Pending {
        MPI_Request request;
        std::vector<unsigned char> bytes;
    };
    std::list<Pending> pending_;  // a list: MPI holds the buffers' addresses until completion
    uint64_t bytes_sent_ = 0;
    uint64_t bytes_received_ = 0;
};

}  // namespace candela
