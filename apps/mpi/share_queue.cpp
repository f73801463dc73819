#include "share_queue.h"

namespace whitted::mpi {

ShareQueue::ShareQueue(const Integrator& integrator, const RenderJob& job, const TileGrid& grid, int rank,
                       TestKnobs knobs)
    : integrator_(integrator), job_(job), grid_(grid), rank_(rank), knobs_(knobs) {
    job_.cancel = &cancel_;
    thread_ = std::thread([this] { run(); });
}

ShareQueue::~ShareQueue() {
    {
        std::lock_guard lock(mutex_);
        closing_ = true;
    }
    cancel_ = true;
    wake_.notify_all();
    thread_.join();
}

void ShareQueue::push(std::vector<int> tiles) {
    {
        std::lock_guard lock(mutex_);
        queued_.push_back(std::move(tiles));
    }
    wake_.notify_all();
}

std::optional<RenderedShare> ShareQueue::pop_finished() {
    std::lock_guard lock(mutex_);
    if (finished_.empty()) return std::nullopt;
    RenderedShare s = std::move(finished_.front());
    finished_.pop_front();
    return s;
}

int ShareQueue::pending() const {
    std::lock_guard lock(mutex_);
    return int(queued_.size() + finished_.size()) + rendering_;
}

void ShareQueue::cancel() {
    std::lock_guard lock(mutex_);
    cancel_ = true;
    queued_.clear();
}

double ShareQueue::busy_seconds() const {
    std::lock_guard lock(mutex_);
    return busy_;
}

void ShareQueue::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return closing_ || !queued_.empty(); });
        if (closing_) return;
        std::vector<int> tiles = std::move(queued_.front());
        queued_.pop_front();
        ++rendering_;
        lock.unlock();
        RenderedShare share = render_share(integrator_, job_, grid_, tiles, rank_, knobs_);
        lock.lock();
        busy_ += share.seconds;
        --rendering_;
        finished_.push_back(std::move(share));
    }
}

}  // namespace whitted::mpi
