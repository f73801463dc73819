// Rank 0: drives the render session (session/session.h) as whitted does; each pass's tiles are
// handed out to the ranks (schedule.h) with the pixels they continue from, rank 0 renders its own
// share on its own thread, every share is merged into the session's film, duplicates are
// checked, and the image is written as whitted writes it.
#include <mpi.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <list>
#include <thread>

#include "load_report.h"
#include "progress.h"
#include "protocol.h"
#include "ranks.h"
#include "schedule.h"
#include "session/run_limits.h"
#include "session/session.h"
#include "session_run.h"
#include "share_queue.h"

namespace whitted::mpi {
namespace {

using cli::RenderOptions;
using cli::SessionCheckpoint;
using cli::SessionOutcome;

using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// Rank 0's progress: tiles, rays/s, ETA and tiles per rank; rewritten in place on a terminal,
// a line every ten seconds otherwise (a batch job's log).
class Progress {
public:
    Progress(int total, int ranks, bool enabled) : total_(total), per_rank_(std::size_t(ranks), 0), enabled_(enabled) {}
    void add(int rank, int tiles, std::uint64_t rays) {
        per_rank_[std::size_t(rank)] += tiles;
        done_ += tiles;
        rays_ += rays;
    }
    void draw(bool last = false) {
        if (!enabled_) return;
        const auto now = Clock::now();
        if (!last && now - drawn_ < (tty_ ? std::chrono::milliseconds(200) : std::chrono::seconds(10))) return;
        drawn_ = now;
        const double t = seconds(now - start_), f = total_ ? double(done_) / total_ : 1.0, eta = f > 0 ? t * (1 - f) / f : 0.0;
        char head[160];
        std::snprintf(head, sizeof head, "tiles %d/%d (%.1f%%)  %.2f Mrays/s  elapsed %.1fs  eta %.1fs", done_, total_,
                      100 * f, t > 0 ? double(rays_) / t * 1e-6 : 0.0, t, eta);
        std::string full = std::string(head) + "  per rank";
        for (int n : per_rank_) full += " " + std::to_string(n);
        if (tty_) {
            // On a terminal, fitted to its width (each update wrapping into a new line otherwise):
            // without the ranks' counts, then whitted's own forms, down to the percentage.
            std::vector<std::string> forms = {full, head};
            for (std::string& form : cli::progress_forms(f, t, eta)) forms.push_back(std::move(form));
            std::fprintf(stderr, "\r\033[K%s", cli::fit_to_width(forms, cli::terminal_columns(STDERR_FILENO)).c_str());
        } else {
            std::fprintf(stderr, "%s\n", full.c_str());
        }
        std::fflush(stderr);
    }
    void finish() {
        if (enabled_ && tty_) std::fprintf(stderr, "\r\033[K");
    }
    std::uint64_t rays() const { return rays_; }
    int tiles_of(int rank) const { return per_rank_[std::size_t(rank)]; }

private:
    int total_, done_ = 0;
    std::vector<int> per_rank_;
    std::uint64_t rays_ = 0;
    bool enabled_, tty_ = isatty(STDERR_FILENO) != 0;
    Clock::time_point start_ = Clock::now(), drawn_ = start_;
};

// A pass's tiles rendered by every rank: the session's PassRenderer in whitted-mpi.
class RankPasses : public PassRenderer {
public:
    RankPasses(const RankSetup& setup, int total_tiles)
        : s(setup), progress(total_tiles, setup.ranks, !setup.options->quiet),
          threads_of(std::size_t(setup.ranks), 1), parked(std::size_t(setup.ranks), 0),
          bye(std::size_t(setup.ranks), false), stats(std::size_t(setup.ranks)) {
        bye[0] = true;  // rank 0 talks to itself without messages
    }

    RenderStats render(const Integrator& integrator, const RenderJob& job, const std::vector<Tile>& tiles,
                       const Film* before, Film& into) override;
    // The end of the job: every rank told there is no more work, and stopped; waits for their
    // goodbyes (a while: a rank that does not answer is given up).
    void end_job(bool patient);
    // Tells every rank the exit code. False if a rank never said goodbye (MPI_Finalize could then
    // wait for it forever).
    bool finish(int code);

    // The progress line's count of tiles (those of every pass, less the resumed).
    void start_progress(int tiles) { progress = Progress(tiles, s.ranks, !s.options->quiet); }

    std::string mismatch;  // two ranks rendered a tile to different bytes
    void print_stats(double wall, int passes_tiles) const;

private:
    void merge_tile(int rank, int t, const Film& from);
    void reply(int rank);
    void receive(const MPI_Status& st);
    std::shared_ptr<Share> share_of(std::vector<int> tiles) const;
    bool all_bye() const { return std::find(bye.begin(), bye.end(), false) == bye.end(); }
    void complete_sends();

    const RankSetup& s;
    struct Send {
        MPI_Request request;
        std::vector<char> bytes;
    };
    std::list<Send> sends;  // assignments on their way
    Progress progress;
    std::unique_ptr<ShareQueue> local;
    std::vector<int> threads_of;  // per rank, from its first request
    std::vector<int> parked;      // requests kept for want of work (answered when a pass begins or the job ends)
    std::vector<bool> bye;
    std::vector<WorkerStats> stats;
    RayCounts local_rays;  // rank 0's
    bool job_over = false;
    // The pass under way.
    int pass = 0;
    std::unique_ptr<Schedule> schedule;
    const RenderJob* job = nullptr;
    const Film* before = nullptr;
    Film* into = nullptr;
    int tiles_done = 0;
    int duplicates = 0;  // of the passes so far
    double service_total = 0, service_max = 0;
    long services = 0;
    std::uint64_t bytes_received = 0;
};

std::shared_ptr<Share> RankPasses::share_of(std::vector<int> tiles) const {
    auto share = std::make_shared<Share>();
    share->pass = pass;
    if (job) {
        share->sample_begin = job->sample_begin;
        share->sample_end = job->sample_end;
    }
    share->tiles = std::move(tiles);
    return share;
}

// A share's tile t has arrived in `from`: keep the first copy, compare any other with it; the tile
// is done (checkpointed, counted) once the copies the schedule asks for are in.
void RankPasses::merge_tile(int rank, int t, const Film& from) {
    const Tile r = s.grid.tile(t);
    const int copy = schedule->arrive(t);
    if (copy == 1) into->copy_from(from, r);
    if (copy == schedule->copies()) {
        ++tiles_done;
        progress.add(rank, 1, 0);
        if (job->on_tile) job->on_tile(r);
    }
    if (copy > 1 && !same_pixels(*into, from, r) && mismatch.empty()) {
        mismatch = "rank " + std::to_string(rank) + " rendered tile " + std::to_string(t) + " (pixels " +
                   std::to_string(r.x0) + "," + std::to_string(r.y0) +
                   ") to other bytes than the rank that rendered it first: the ranks do not compute alike "
                   "(another CPU, library or build?)";
    }
}

// A request of `rank`: the next tiles of the pass under way, kept for later when there are none
// (another pass may follow), no tiles once the job is over.
void RankPasses::reply(int rank) {
    std::vector<int> tiles;
    if (!job_over) {
        if (schedule && mismatch.empty()) tiles = schedule->next(rank, threads_of[std::size_t(rank)]);
        if (tiles.empty()) {
            ++parked[std::size_t(rank)];
            return;
        }
    }
    const std::shared_ptr<Share> share = share_of(std::move(tiles));
    std::vector<char> msg =
        pack_assign(*share, s.grid, share->tiles.empty() || job->sample_begin == 0 ? nullptr : before,
                    share->tiles.empty() ? nullptr : job->active);
    // Not blocking: an assignment carries pixels, and the rank may be sending a large result at
    // the same moment (two blocking sends of large messages wait for each other).
    sends.emplace_back();
    sends.back().bytes = std::move(msg);
    MPI_Isend(sends.back().bytes.data(), int(sends.back().bytes.size()), MPI_BYTE, rank, kAssign, MPI_COMM_WORLD,
              &sends.back().request);
}

void RankPasses::complete_sends() {
    for (auto it = sends.begin(); it != sends.end();) {
        int done = 0;
        MPI_Test(&it->request, &done, MPI_STATUS_IGNORE);
        it = done ? sends.erase(it) : std::next(it);
    }
}

void RankPasses::receive(const MPI_Status& st) {
    const auto t0 = Clock::now();
    const int from = st.MPI_SOURCE;
    int count = 0;
    MPI_Get_count(&st, MPI_BYTE, &count);
    std::vector<char> msg(std::size_t(std::max(count, 1)));
    MPI_Recv(msg.data(), count, MPI_BYTE, from, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    bytes_received += std::size_t(count);
    if (st.MPI_TAG == kRequest) {
        std::int32_t threads = 1;
        std::memcpy(&threads, msg.data(), sizeof threads);
        threads_of[std::size_t(from)] = threads;
        reply(from);
    } else if (st.MPI_TAG == kResult) {
        ResultHeader h;
        std::memcpy(&h, msg.data(), sizeof h);
        const char* p = msg.data() + sizeof h;
        const char* end = msg.data() + count;
        // Tiles of a pass that has ended came too late (duplicates at its tail): not merged.
        for (int i = 0; i < h.tiles && h.pass == pass && schedule; ++i) {
            std::int32_t t = 0;
            std::memcpy(&t, p, sizeof t);
            p += sizeof t;
            Film one(s.grid.width, s.grid.height, s.grid.tile(t));
            if (!read_tile_pixels(p, end, s.grid.tile(t), one)) break;
            merge_tile(from, t, one);
        }
        progress.add(from, 0, h.rays);
        if (h.want_more) reply(from);
    } else if (st.MPI_TAG == kBye) {
        std::memcpy(&stats[std::size_t(from)], msg.data(), sizeof(WorkerStats));
        bye[std::size_t(from)] = true;
    }
    const double dt = seconds(Clock::now() - t0);
    service_total += dt;
    service_max = std::max(service_max, dt);
    ++services;
}

RenderStats RankPasses::render(const Integrator& integrator, const RenderJob& pass_job,
                               const std::vector<Tile>& tiles, const Film* pass_before, Film& pass_into) {
    const auto start = Clock::now();
    if (!local) local = std::make_unique<ShareQueue>(integrator, pass_job, s.grid, 0, s.knobs);
    ++pass;
    job = &pass_job;
    before = pass_before;
    into = &pass_into;
    tiles_done = 0;
    // The tiles not in this pass (done before a resume) count as done for the schedule.
    std::vector<bool> done(std::size_t(s.grid.count()), true);
    for (const Tile& t : tiles) done[std::size_t(s.grid.index_of(t))] = false;
    schedule = std::make_unique<Schedule>(s.grid.count(), s.ranks, s.schedule_seed, done, s.verify ? 2 : 1);
    // Requests kept from the pass before are answered first.
    for (int r = 1; r < s.ranks; ++r)
        for (int n = parked[std::size_t(r)]; n > 0; --n) {
            --parked[std::size_t(r)];
            reply(r);
        }
    const bool first = pass_job.sample_begin == 0;
    bool stopping = false;
    Clock::time_point stop_at{};
    for (;;) {
        bool busy = false;
        const auto now = Clock::now();
        if (!stopping && ((pass_job.cancel && pass_job.cancel->load(std::memory_order_relaxed)) || !mismatch.empty())) {
            // Ctrl-C or a time limit: hand out nothing more. A later pass is dropped whole (the last
            // whole one stands); in the first, the tiles in flight may come in for a moment.
            stopping = true;
            schedule->stop();
            stop_at = first && mismatch.empty() ? now + std::chrono::milliseconds(int(s.grace_seconds * 1000)) : now;
        }
        if (schedule->all_done() || (stopping && now >= stop_at)) break;
        while (!stopping && local->pending() < 2) {
            std::vector<int> mine = schedule->next(0, s.threads);
            if (mine.empty()) break;
            std::shared_ptr<Share> share = share_of(std::move(mine));
            if (!first) {
                share->before = Film(s.grid.width, s.grid.height, box_of(s.grid, share->tiles));
                for (int t : share->tiles) share->before.copy_from(*pass_before, s.grid.tile(t));
            }
            if (pass_job.active) share->active = *pass_job.active;
            local->push(std::move(share));
        }
        bool last = false;
        while (auto share = local->pop_finished(last)) {
            busy = true;
            if (share->pass == pass)
                for (int t : share->tiles) merge_tile(0, t, share->film);
            progress.add(0, 0, share->rays);
            local_rays += share->counts;
        }
        int flag = 0;
        MPI_Status st;
        while (MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st), flag) {
            busy = true;
            receive(st);
        }
        complete_sends();
        progress.draw();
        if (!busy) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    // What rank 0 still renders of this pass is of no more use (tiles handed out twice at the tail).
    local->drop();
    schedule->stop();
    duplicates += schedule->duplicates_sent();
    RenderStats out;
    out.tiles_total = int(tiles.size());
    out.tiles_done = tiles_done;
    out.cancelled = !schedule->all_done();
    // Between passes nothing is merged (the pass's job and films are the session's, for this call).
    schedule.reset();
    job = nullptr;
    before = nullptr;
    into = nullptr;
    out.threads = s.threads;
    out.seconds = seconds(Clock::now() - start);
    return out;
}

void RankPasses::end_job(bool patient) {
    job_over = true;
    if (local) local->cancel();
    for (int r = 1; r < s.ranks; ++r) {
        if (!bye[std::size_t(r)]) MPI_Send(nullptr, 0, MPI_BYTE, r, kCancel, MPI_COMM_WORLD);
        for (; parked[std::size_t(r)] > 0; --parked[std::size_t(r)]) reply(r);
    }
    const auto give_up_at = Clock::now() + (patient ? std::chrono::seconds(60) : std::chrono::seconds(1));
    while ((!all_bye() || !sends.empty()) && Clock::now() < give_up_at) {
        int flag = 0;
        MPI_Status st;
        bool busy = false;
        while (MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st), flag) {
            busy = true;
            receive(st);
        }
        complete_sends();
        if (!busy) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    progress.draw(true);
    progress.finish();
}

bool RankPasses::finish(int code) {
    const std::int32_t c = code;
    for (int r = 1; r < s.ranks; ++r) MPI_Send(&c, 1, MPI_INT32_T, r, kFinish, MPI_COMM_WORLD);
    return all_bye();
}

void RankPasses::print_stats(double wall, int passes_tiles) const {
    std::fprintf(stderr,
                 "ranks %d, tiles %d (%dx%d px) a pass, %d tiles of passes, %d %s; setup %.3fs (broadcast %zu bytes "
                 "in %.3fs); render %.3fs, %.2f Mrays/s\n",
                 s.ranks, s.grid.count(), s.grid.size, s.grid.size, passes_tiles,
                 s.verify ? passes_tiles : duplicates,
                 s.verify ? "rendered twice and compared" : "duplicates sent", s.setup_seconds, s.broadcast_bytes,
                 s.broadcast_seconds, wall, wall > 0 ? double(progress.rays()) / wall * 1e-6 : 0.0);
    std::fprintf(stderr, "master: %ld requests served, %.1f us mean, %.1f us max; %llu bytes received (%.0f per tile)\n",
                 services, services ? service_total / double(services) * 1e6 : 0.0, service_max * 1e6,
                 (unsigned long long)bytes_received, passes_tiles ? double(bytes_received) / passes_tiles : 0.0);
    std::fprintf(stderr, "rank 0: %d threads, %d tiles, busy %.3fs, idle %.3fs\n", s.threads, progress.tiles_of(0),
                 local ? local->busy_seconds() : 0.0, std::max(0.0, wall - (local ? local->busy_seconds() : 0.0)));
    for (int r = 1; r < s.ranks; ++r) {
        const WorkerStats& w = stats[std::size_t(r)];
        std::fprintf(stderr, "rank %d: %d threads, %d tiles (%d kept), busy %.3fs, idle %.3fs, sent %llu bytes\n", r,
                     w.threads, w.tiles, progress.tiles_of(r), w.busy, std::max(0.0, w.wall - w.busy),
                     (unsigned long long)w.bytes_sent);
    }
    RayCounts all = local_rays;
    for (int r = 1; r < s.ranks; ++r) all += stats[std::size_t(r)].rays;
    std::fprintf(stderr, "all ranks (tiles handed out twice counted twice):\n");
    cli::print_rays(all, wall);
}

}  // namespace

int run_master(const RankSetup& s) {
    const RenderOptions& o = *s.options;
    const auto start = Clock::now();
    RankPasses ranks(s, 0);
    Session session(s.scene, s.job, &ranks);
    SessionCheckpoint checkpoint;
    if (cli::uses_checkpoint(o.settings))
        if (const int code = checkpoint.start(o, *s.loaded, s.inputs, session, "whitted-mpi"); code != cli::kExitOk) {
            ranks.end_job(false);
            ranks.finish(code);
            return code;
        }
    ranks.start_progress(s.grid.count() * int(session.pass_ends().size()) - checkpoint.tiles_resumed());
    int tiles_merged = 0;
    const SessionOutcome outcome = run_passes(session, *s.limits, checkpoint, [&](const Tile&, const Film&) {
        if (++tiles_merged == s.interrupt_after_tiles) std::raise(SIGINT);
    });
    const double render_wall = seconds(Clock::now() - start);  // the image write is not rendering
    ranks.end_job(outcome.complete);
    int code = cli::kExitOk;
    if (!ranks.mismatch.empty()) {
        std::cerr << "whitted-mpi: error: " << ranks.mismatch << "; nothing written\n";
        code = kExitMismatch;
    } else {
        // A time limit that ran out exits 130, as a batch system's SIGTERM (4 means two ranks disagreed).
        code = s.frame >= 0 ? cli::write_frame(session, outcome, o, *s.limits, s.frame, "whitted-mpi",
                                               cli::kExitInterrupted)
                            : write_session(session, outcome, o, *s.limits, "whitted-mpi", cli::kExitInterrupted);
    }
    if (o.stats) ranks.print_stats(render_wall, s.grid.count() * session.passes_done() + (outcome.complete ? 0 : outcome.last.tiles_done));
    if (!ranks.finish(code)) {  // some rank never finished: MPI_Finalize could wait for it forever
        std::fflush(stderr);
        std::_Exit(code);
    }
    return code;
}

}  // namespace whitted::mpi
