#pragma once
// MPI for the length of a command: initialised in the constructor (MPI_THREAD_FUNNELED: only the
// thread that made the session calls MPI; render threads never do), finalised in the destructor.
// Built only when MPI is found (CANDELA_HAVE_MPI).
#include <cstdint>
#include <string>
#include <vector>

namespace candela {

class MpiSession {
  public:
    MpiSession(int* argc, char*** argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    // The number of ranks on this rank's host (to share its cores), and the host's name.
    int local_size() const { return local_size_; }
    const std::string& host() const { return host_; }

    // Every rank's `value`, in rank order, on rank 0 (empty on the others). Collective: every
    // rank must call it.
    std::vector<uint64_t> gather(uint64_t value) const;

    // Rank 0's `bytes`, on every rank (what the others pass is ignored). Collective.
    std::string broadcast(std::string bytes) const;

    // Ends every rank of the job at once with `exit_code` (MPI_Abort): for an error on one rank
    // that the others cannot know of, instead of leaving them waiting.
    [[noreturn]] void abort(int exit_code) const;

  private:
    int rank_ = 0, size_ = 1, local_size_ = 1;
    std::string host_;
};

}  // namespace candela
