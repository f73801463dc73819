#include "share_queue.h"

#include <algorithm>

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

void ShareQueue::push(std::shared_ptr<const Share> share) {
    {
        std::lock_guard lock(mutex_);
        if (cancelled_) return;
        queued_.push_back(std::move(share));
    }
    wake_.notify_all();
}

std::optional<RenderedShare> ShareQueue::pop_finished(bool& last_of_share) {
    std::lock_guard lock(mutex_);
    if (finished_.empty()) return std::nullopt;
    RenderedShare s = std::move(finished_.front().first);
    last_of_share = finished_.front().second;
    finished_.pop_front();
    return s;
}

int ShareQueue::pending() const {
    std::lock_guard lock(mutex_);
    int shares = int(queued_.size()) + rendering_;
    for (const auto& f : finished_) shares += f.second ? 1 : 0;
    return shares;
}

void ShareQueue::cancel() {
    std::lock_guard lock(mutex_);
    cancel_ = true;
    cancelled_ = true;
    queued_.clear();
}

void ShareQueue::drop() {
    std::unique_lock lock(mutex_);
    if (cancelled_) return;
    cancel_ = true;
    queued_.clear();
    idle_.wait(lock, [&] { return rendering_ == 0; });
    finished_.clear();
    cancel_ = false;
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
        const std::shared_ptr<const Share> share = std::move(queued_.front());
        queued_.pop_front();
        const std::vector<int>& tiles = share->tiles;
        ++rendering_;
        const std::size_t batch = std::size_t(std::max(16, 4 * job_.threads));
        for (std::size_t at = 0; at < tiles.size(); at += batch) {
            const std::size_t end = std::min(tiles.size(), at + batch);
            const std::vector<int> part(tiles.begin() + std::ptrdiff_t(at), tiles.begin() + std::ptrdiff_t(end));
            lock.unlock();
            RenderedShare done = render_share(integrator_, job_, grid_, *share, part, rank_, knobs_);
            lock.lock();
            busy_ += done.seconds;
            const bool last = end == tiles.size() || cancel_;
            finished_.emplace_back(std::move(done), last);
            if (last) {
                --rendering_;
                idle_.notify_all();
                break;
            }
        }
    }
}

}  // namespace whitted::mpi
