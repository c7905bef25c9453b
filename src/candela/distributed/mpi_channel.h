#pragma once
// Point-to-point messages for the MPI renderer, without blocking: sends are MPI_Isend kept until
// complete (two ranks each blocked in a large MPI_Send to the other would wait for ever), and
// receives are matched as they arrive (MPI_Improbe) and completed in the background
// (MPI_Imrecv): a message above the transport's eager limit (a tile's values: 6 KiB) moves only
// when its sender makes progress, and a blocking receive would spin until it did. So the calling
// thread never waits, and can also watch its render threads and stop signals. Messages are
// delivered in the order they were sent (per sender, as MPI matches them). A channel receives one
// tag; only the thread that owns the MpiSession uses it.
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
    // The next message with `tag` from any rank, if one has arrived whole.
    std::optional<ReceivedMessage> try_receive(int tag);
    // Frees the buffers of completed sends.
    void progress();
    // Waits until every send and every receive already matched is complete (the receivers must go
    // on receiving, and the senders on sending).
    void wait_all();

    uint64_t bytes_sent() const { return bytes_sent_; }
    uint64_t bytes_received() const { return bytes_received_; }

  private:
    struct Pending {
        MPI_Request request;
        std::vector<unsigned char> bytes;
    };
    struct Incoming {
        MPI_Request request;
        int source;
        std::vector<unsigned char> bytes;
    };
    std::list<Pending> pending_;    // a list: MPI holds the buffers' addresses until completion
    std::list<Incoming> incoming_;  // matched, in matching order
    uint64_t bytes_sent_ = 0;
    uint64_t bytes_received_ = 0;
};

}  // namespace candela
