// A worker rank: keeps two requests in flight, renders what it is given (tiles of a pass, with the
// pixels they continue from) on its own thread, sends each share back in batches as they finish
// (the last with the next request), and stops when told or when the job has no more work.
#include <mpi.h>

#include <chrono>
#include <cstring>
#include <thread>

#include "protocol.h"
#include "ranks.h"
#include "share_queue.h"

namespace whitted::mpi {

int run_worker(const RankSetup& s) {
    const auto start = std::chrono::steady_clock::now();
    ShareQueue queue(*s.integrator, s.job, s.grid, s.rank, s.knobs);
    WorkerStats stats;
    stats.threads = s.threads;
    const std::int32_t threads = s.threads;
    int in_flight = 2;
    for (int i = 0; i < in_flight; ++i) MPI_Send(&threads, 1, MPI_INT32_T, 0, kRequest, MPI_COMM_WORLD);
    bool no_more = false, said_bye = false;
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
                return code;
            }
            if (st.MPI_TAG == kCancel) {
                no_more = true;
                queue.cancel();
            } else if (st.MPI_TAG == kAssign) {
                --in_flight;
                auto share = std::make_shared<Share>();
                if (!unpack_assign(msg.data(), msg.data() + count, s.grid, *share) || share->tiles.empty())
                    no_more = true;
                else
                    queue.push(std::move(share));
            }
        }
        // Ctrl-C (mpirun's SIGTERM): ask for nothing more; rank 0 says when to stop rendering.
        if (s.interrupted->load(std::memory_order_relaxed)) no_more = true;
        bool last = false;
        while (auto share = queue.pop_finished(last)) {
            busy = true;
            // The share's last batch carries the next request.
            const bool more = last && !no_more;
            const std::vector<char> bytes = pack_result(*share, s.grid, more);
            // Blocking: large messages move only while both sides drive them, and the render
            // thread goes on meanwhile.
            MPI_Send(bytes.data(), int(bytes.size()), MPI_BYTE, 0, kResult, MPI_COMM_WORLD);
            stats.bytes_sent += bytes.size();
            stats.tiles += std::int32_t(share->tiles.size());
            stats.rays += share->counts;
            if (more) ++in_flight;
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
