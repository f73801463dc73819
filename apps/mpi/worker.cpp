// A worker rank: keeps two requests in flight, renders what it is given on its own thread, sends
// each share back as it finishes (with the next request), and stops when told or out of work.
#include <mpi.h>

#include <chrono>
#include <list>
#include <thread>

#include "protocol.h"
#include "ranks.h"
#include "share_queue.h"

namespace whitted::mpi {
namespace {

struct PendingSend {
    MPI_Request request;
    std::vector<char> bytes;
};

}  // namespace

int run_worker(const RankSetup& s) {
    const auto start = std::chrono::steady_clock::now();
    ShareQueue queue(*s.integrator, s.job, s.grid, s.rank, s.knobs);
    WorkerStats stats;
    stats.threads = s.threads;
    const std::int32_t threads = s.threads;
    int in_flight = 2;
    for (int i = 0; i < in_flight; ++i) MPI_Send(&threads, 1, MPI_INT32_T, 0, kRequest, MPI_COMM_WORLD);
    bool no_more = false, said_bye = false;
    std::list<PendingSend> sends;
    for (;;) {
        bool busy = false;
        int flag = 0;
        MPI_Status st;
        MPI_Iprobe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
        if (flag) {
            busy = true;
            int count = 0;
            MPI_Get_count(&st, MPI_BYTE, &count);
            std::vector<char> msg(std::size_t(std::max(count, 1)));
            MPI_Recv(msg.data(), count, MPI_BYTE, 0, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (st.MPI_TAG == kFinish) {
                std::int32_t code = 0;
                std::memcpy(&code, msg.data(), sizeof code);
                for (auto& p : sends) MPI_Wait(&p.request, MPI_STATUS_IGNORE);
                return code;
            }
            if (st.MPI_TAG == kCancel) {
                no_more = true;
                queue.cancel();
            } else if (st.MPI_TAG == kAssign) {
                --in_flight;
                std::vector<int> tiles(std::size_t(count) / sizeof(std::int32_t));
                std::memcpy(tiles.data(), msg.data(), tiles.size() * sizeof(std::int32_t));
                if (tiles.empty()) no_more = true;
                else queue.push(std::move(tiles));
            }
        }
        // Ctrl-C (mpirun's SIGTERM): ask for nothing more; rank 0 says when to stop rendering.
        if (s.interrupted->load(std::memory_order_relaxed)) no_more = true;
        while (auto share = queue.pop_finished()) {
            busy = true;
            const bool more = !no_more;
            sends.push_back({MPI_REQUEST_NULL, pack_result(*share, s.grid, more)});
            PendingSend& p = sends.back();
            MPI_Isend(p.bytes.data(), int(p.bytes.size()), MPI_BYTE, 0, kResult, MPI_COMM_WORLD, &p.request);
            stats.bytes_sent += p.bytes.size();
            stats.tiles += std::int32_t(share->tiles.size());
            if (more) ++in_flight;
        }
        for (auto it = sends.begin(); it != sends.end();) {
            int done = 0;
            MPI_Test(&it->request, &done, MPI_STATUS_IGNORE);
            it = done ? sends.erase(it) : std::next(it);
        }
        if (!said_bye && in_flight == 0 && queue.pending() == 0) {
            stats.busy = queue.busy_seconds();
            stats.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            MPI_Send(&stats, sizeof stats, MPI_BYTE, 0, kBye, MPI_COMM_WORLD);
            said_bye = true;
        }
        // Blocking MPI calls spin; a short sleep leaves the cores to the render threads.
        if (!busy) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
}

}  // namespace whitted::mpi
