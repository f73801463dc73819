// Rank 0: hands out tiles (schedule.h), renders its own share on its own thread, merges every
// share into the one film, checks duplicates, checkpoints, reports progress and writes the image.
#include <mpi.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <thread>

#include "session/image_text.h"
#include "session/session.h"
#include "film/image_io.h"
#include "progress.h"
#include "session/run_limits.h"
#include "protocol.h"
#include "ranks.h"
#include "schedule.h"
#include "share_queue.h"

namespace whitted::mpi {
namespace {

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

struct Master {
    const RankSetup& s;
    Film film;
    Schedule schedule;
    CheckpointWriter checkpoint;
    Progress progress;
    std::vector<int> threads_of;  // per rank, from its first request
    std::vector<bool> bye;
    std::vector<WorkerStats> stats;
    std::string mismatch;
    double service_total = 0, service_max = 0;
    long services = 0;
    std::uint64_t bytes_received = 0;

    Master(const RankSetup& setup, Film f, const std::vector<bool>& done)
        : s(setup), film(std::move(f)),
          schedule(setup.grid.count(), setup.ranks, setup.schedule_seed, done, setup.verify ? 2 : 1),
          progress(setup.grid.count(), setup.ranks, !setup.options->quiet),
          threads_of(std::size_t(setup.ranks), 1), bye(std::size_t(setup.ranks), false),
          stats(std::size_t(setup.ranks)) {
        bye[0] = true;  // rank 0 talks to itself without messages
    }

    // A share's tile t has arrived in `from`: keep the first copy, compare any other with it; the
    // tile is done (checkpointed, counted) once the copies the schedule asks for are in.
    void merge_tile(int rank, int t, const Film& from) {
        const Tile r = s.grid.tile(t);
        const int copy = schedule.arrive(t);
        if (copy == 1) film.copy_from(from, r);
        if (copy == schedule.copies()) {
            checkpoint.append(t, film, s.job.sampling.samples_per_pixel());
            progress.add(rank, 1, 0);
        }
        if (copy > 1 && !same_pixels(film, from, r) && mismatch.empty()) {
            mismatch = "rank " + std::to_string(rank) + " rendered tile " + std::to_string(t) + " (pixels " +
                       std::to_string(r.x0) + "," + std::to_string(r.y0) +
                       ") to other bytes than the rank that rendered it first: the ranks do not compute alike "
                       "(another CPU, library or build?)";
        }
    }

    void reply(int rank) {
        const std::vector<int> tiles = mismatch.empty() ? schedule.next(rank, threads_of[std::size_t(rank)])
                                                         : std::vector<int>{};
        const std::vector<std::int32_t> msg(tiles.begin(), tiles.end());
        MPI_Send(msg.data(), int(msg.size()), MPI_INT32_T, rank, kAssign, MPI_COMM_WORLD);
    }

    void receive(const MPI_Status& st) {
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
            for (int i = 0; i < h.tiles; ++i) {
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

    void cancel_workers() {
        for (int r = 1; r < s.ranks; ++r)
            if (!bye[std::size_t(r)]) MPI_Send(nullptr, 0, MPI_BYTE, r, kCancel, MPI_COMM_WORLD);
    }

    bool all_bye() const { return std::find(bye.begin(), bye.end(), false) == bye.end(); }

    std::string why_stopped() const {
        if (!s.deadline || !s.deadline->timed_out()) return "interrupted";
        char limit[32];
        std::snprintf(limit, sizeof limit, "%g s", timeout_seconds(s.options->settings));
        return std::string("the time limit of ") + limit + " (--timeout) ran out";
    }

    int run();
    // The film to `path` with whitted's words about it: every sample of the schedule's passes when
    // every tile is in (a partial image: its tiles have them, the others none).
    std::string write_film(const std::string& path) const {
        const int passes = int(sample_passes(s.job.sampling).size());
        const ImageText text = render_image_text(s.options->settings, s.job.sampling.samples_per_pixel(),
                                                 schedule.all_done() ? passes : 0, passes);
        if (is_linear_output(path)) {
            LinearImage image = film.to_linear();
            image.text = text;
            return write_linear_image(image, path);
        }
        Image image = film.to_image(view_transform(s.options->settings));
        image.text = text;
        return write_image(image, path);
    }
    void print_stats(double wall, double local_busy) const;
};

int Master::run() {
    const auto start = Clock::now();
    if (!s.checkpoint.empty()) {
        std::vector<bool> done(std::size_t(s.grid.count()));
        for (int t = 0; t < s.grid.count(); ++t) done[std::size_t(t)] = schedule.is_done(t);
        if (std::string err = checkpoint.open(s.checkpoint, s.checkpoint_key,
                                              {{&film, done, s.job.sampling.samples_per_pixel()}}, s.checkpoint_seconds);
            !err.empty())
            std::cerr << "whitted-mpi: warning: " << err << " (rendering without one)\n";
    }
    ShareQueue local(*s.integrator, s.job, s.grid, 0, s.knobs);
    bool stopping = false, cancelled = false;
    Clock::time_point cancel_at{}, give_up_at{};
    for (;;) {
        bool busy = false;
        const auto now = Clock::now();
        if (!stopping && (s.interrupted->load(std::memory_order_relaxed) || !mismatch.empty())) {
            // Ctrl-C: hand out nothing more, let the tiles in flight come in for a moment.
            stopping = true;
            schedule.stop();
            cancel_at = mismatch.empty() ? now + std::chrono::milliseconds(int(s.grace_seconds * 1000)) : now;
        }
        if (!cancelled && ((stopping && now >= cancel_at) || schedule.all_done())) {
            // Done (duplicates still out are no longer needed) or out of patience.
            cancelled = true;
            schedule.stop();
            local.cancel();
            cancel_workers();
            give_up_at = now + std::chrono::milliseconds(stopping ? 300 : 60000);
        }
        while (!cancelled && local.pending() < 2) {
            std::vector<int> tiles = schedule.next(0, s.threads);
            if (tiles.empty()) break;
            local.push(std::move(tiles));
        }
        bool last = false;
        while (auto share = local.pop_finished(last)) {
            busy = true;
            for (int t : share->tiles) merge_tile(0, t, share->film);
            progress.add(0, 0, share->rays);
        }
        int flag = 0;
        MPI_Status st;
        while (MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st), flag) {
            busy = true;
            receive(st);
        }
        progress.draw();
        checkpoint.flush();
        if (cancelled && all_bye() && local.pending() == 0) break;
        if (cancelled && Clock::now() > give_up_at) break;  // a rank that does not answer: write what is here
        if (!busy) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    const double render_wall = seconds(Clock::now() - start);  // the image write is not rendering
    progress.draw(true);
    progress.finish();
    checkpoint.flush(true);

    int code = cli::kExitOk;
    // An interrupted job never replaces the output (a good image may be there): its part goes beside
    // it, if there is one and it can be written quickly.
    const std::string written = schedule.all_done() ? s.options->output : partial_image_path(s.options->output);
    const std::string no_partial =
        schedule.all_done() ? "" : why_no_partial_image(schedule.done_count(), s.grid.width, s.grid.height);
    if (!mismatch.empty()) {
        std::cerr << "whitted-mpi: error: " << mismatch << "; nothing written\n";
        code = kExitMismatch;
    } else if (!no_partial.empty()) {
        std::cerr << "whitted-mpi: " << why_stopped() << ": " << no_partial << ": nothing written\n";
        code = cli::kExitInterrupted;
    } else if (std::string err = write_film(written); !err.empty()) {
        std::cerr << "whitted-mpi: error: " << err << "\n";
        code = cli::kExitIo;
    } else if (!schedule.all_done() && s.deadline && s.deadline->timed_out()) {
        std::cerr << "whitted-mpi: error: the time limit of " << timeout_seconds(s.options->settings)
                  << " s (--timeout) ran out: wrote the " << schedule.done_count() << " of " << schedule.tile_count()
                  << " tiles rendered so far to " << written << " (" << s.options->output << " was not written)\n";
        code = cli::kExitInterrupted;  // as a batch system's SIGTERM (4 means two ranks disagreed)
    } else if (!schedule.all_done()) {
        std::cerr << "whitted-mpi: " << why_stopped() << ": wrote the " << schedule.done_count() << " of "
                  << schedule.tile_count() << " tiles rendered so far to " << written << " (" << s.options->output
                  << " was not written)\n";
        code = cli::kExitInterrupted;
    } else if (!s.options->quiet) {
        std::cerr << "wrote " << s.options->output << "\n";
    }
    if (s.options->stats) print_stats(render_wall, local.busy_seconds());
    const std::int32_t c = code;
    for (int r = 1; r < s.ranks; ++r) MPI_Send(&c, 1, MPI_INT32_T, r, kFinish, MPI_COMM_WORLD);
    if (!all_bye()) {  // some rank never finished: MPI_Finalize could wait for it forever
        std::fflush(stderr);
        std::_Exit(code);
    }
    return code;
}

void Master::print_stats(double wall, double local_busy) const {
    std::fprintf(stderr,
                 "ranks %d, tiles %d (%dx%d px), %d %s; setup %.3fs (broadcast %zu bytes in %.3fs); "
                 "render %.3fs, %.2f Mrays/s\n",
                 s.ranks, s.grid.count(), s.grid.size, s.grid.size,
                 s.verify ? schedule.done_count() : schedule.duplicates_sent(),
                 s.verify ? "rendered twice and compared" : "duplicates sent", s.setup_seconds,
                 s.broadcast_bytes, s.broadcast_seconds, wall, wall > 0 ? double(progress.rays()) / wall * 1e-6 : 0.0);
    std::fprintf(stderr, "master: %ld requests served, %.1f us mean, %.1f us max; %llu bytes received (%.0f per tile)\n",
                 services, services ? service_total / double(services) * 1e6 : 0.0, service_max * 1e6,
                 (unsigned long long)bytes_received,
                 schedule.done_count() ? double(bytes_received) / schedule.done_count() : 0.0);
    std::fprintf(stderr, "rank 0: %d threads, %d tiles, busy %.3fs, idle %.3fs\n", s.threads, progress.tiles_of(0),
                 local_busy, std::max(0.0, wall - local_busy));
    for (int r = 1; r < s.ranks; ++r) {
        const WorkerStats& w = stats[std::size_t(r)];
        std::fprintf(stderr, "rank %d: %d threads, %d tiles (%d kept), busy %.3fs, idle %.3fs, sent %llu bytes\n", r,
                     w.threads, w.tiles, progress.tiles_of(r), w.busy, std::max(0.0, w.wall - w.busy),
                     (unsigned long long)w.bytes_sent);
    }
}

}  // namespace

int run_master(const RankSetup& s) {
    Film film(s.grid.width, s.grid.height);
    std::vector<bool> done;
    if (!s.resume.empty()) {
        if (std::string err = read_checkpoint(s.resume, s.checkpoint_key, s.job.sampling.samples_per_pixel(), film, done,
                                              s.interrupted); !err.empty()) {
            std::cerr << "whitted-mpi: error: " << err << "\n";
            const std::int32_t c = cli::kExitUsage;
            // Workers are waiting for work: tell them the job is over.
            for (int r = 1; r < s.ranks; ++r) {
                std::int32_t threads = 0;
                MPI_Recv(&threads, 1, MPI_INT32_T, r, kRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                MPI_Recv(&threads, 1, MPI_INT32_T, r, kRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                MPI_Send(&c, 1, MPI_INT32_T, r, kFinish, MPI_COMM_WORLD);
            }
            return c;
        }
    }
    if (!s.resume.empty() && !s.options->quiet)
        std::cerr << "whitted-mpi: resuming: " << std::count(done.begin(), done.end(), true) << " of " << s.grid.count()
                  << " tiles from " << s.resume << "\n";
    Master m(s, std::move(film), done);
    return m.run();
}

}  // namespace whitted::mpi
