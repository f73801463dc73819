#pragma once
// The pass loop whitted and whitted-mpi's rank 0 drive a Session with, and what they write after
// it: --time-limit's forecast, Ctrl-C and --timeout, the checkpoint kept up to date, then the
// image (or the part beside it) with the same words about how far the render got.
#include <chrono>
#include <functional>
#include <string>

#include "interrupt.h"
#include "render_options.h"
#include "session/session.h"
#include "session_checkpoint.h"

namespace whitted::cli {

// --timeout and --time-limit of a run that started at `start` (the budget keeps the write's time
// in reserve and counts the load).
class SessionLimits {
public:
    SessionLimits(const RenderSettings& s, std::chrono::steady_clock::time_point start);
    // "--timeout" or "--time-limit" once it ran out, else null.
    const char* ran_out() const;
    bool timed_out() const { return timeout_.timed_out(); }
    bool budget_timed_out() const { return budget_deadline_.timed_out(); }
    // The seconds of whichever ran out (for messages).
    double seconds_of_limit() const;
    double budget() const { return budget_; }  // seconds for load and passes; 0: no --time-limit
    double elapsed() const;

private:
    const RenderSettings& s_;
    std::chrono::steady_clock::time_point start_;
    Deadline timeout_;
    double budget_;
    Deadline budget_deadline_;
};

struct SessionOutcome {
    RenderStats last;             // the last pass begun
    bool budget_reached = false;  // --time-limit: the passes that fitted are done
    bool interrupted = false;     // Ctrl-C, --timeout or the job stopped otherwise
    bool complete = false;        // a whole image: every pass, or those that fitted the budget
};

// Renders the session's passes: each tile to `checkpoint` and `on_tile` (from the threads that
// render), each whole pass to the checkpoint, until done, the budget or a cancel.
SessionOutcome run_passes(Session& session, const SessionLimits& limits, SessionCheckpoint& checkpoint,
                          const std::function<void(const Tile&, const Film&)>& on_tile);

// The session's image to `path`: .exr and .pfm keep the linear values, the 8-bit formats get them
// through the view transform; the settings and the samples reached in the file's text. "" or why not.
std::string write_session_image(const Session& session, const RenderSettings& s, const std::string& path);

// Writes what the session holds to o.output (complete) or beside it (NAME.partial.EXT), with the
// per-term images if asked for, and says so after `program`'s name. Returns the exit code:
// `timeout_code` when a limit ran out before the image was complete.
int write_session(const Session& session, const SessionOutcome& outcome, const RenderOptions& o,
                  const SessionLimits& limits, const char* program, int timeout_code);

// Frame `frame` of --frames after its passes, to o.output: written only whole, for a frame's file is
// what tells the next run of the same command that it is done. The exit code (`timeout_code` when
// --timeout ran out).
int write_frame(const Session& session, const SessionOutcome& outcome, const RenderOptions& o,
                const SessionLimits& limits, int frame, const char* program, int timeout_code);

}  // namespace whitted::cli
