#pragma once
// A rank's render thread: the MPI thread hands it shares of tiles and collects them rendered, so
// that talking to the other ranks never waits for a render and a render never waits for MPI.
// A share comes out in batches of a few tiles per thread as they finish, so rank 0 learns early
// which tiles are done (a big share is not all "still out" until its end, to be duplicated).
#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "tiles.h"

namespace whitted::mpi {

class ShareQueue {
public:
    ShareQueue(const Integrator& integrator, const RenderJob& job, const TileGrid& grid, int rank, TestKnobs knobs);
    ~ShareQueue();

    void push(std::shared_ptr<const Share> share);
    // The next finished batch; `last_of_share` tells the share's last batch.
    std::optional<RenderedShare> pop_finished(bool& last_of_share);
    // Shares queued or being rendered, not yet popped as finished.
    int pending() const;
    // Stops the share being rendered (its finished tiles still come out) and drops the queued ones;
    // nothing is rendered after.
    void cancel();
    // The end of a pass: stops the share being rendered and drops it, the queued and the finished
    // ones (of no more use), then takes new shares again.
    void drop();
    double busy_seconds() const;

private:
    void run();
    const Integrator& integrator_;
    RenderJob job_;
    TileGrid grid_;
    int rank_;
    TestKnobs knobs_;
    std::atomic<bool> cancel_{false};
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::shared_ptr<const Share>> queued_;
    std::deque<std::pair<RenderedShare, bool>> finished_;
    int rendering_ = 0;
    bool closing_ = false, cancelled_ = false;
    std::condition_variable idle_;
    double busy_ = 0;
    std::thread thread_;
};

}  // namespace whitted::mpi
