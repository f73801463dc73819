#include "session_run.h"

#include <algorithm>
#include <iostream>

#include "film/image_io.h"
#include "session/aov_output.h"
#include "session/image_text.h"
#include "session/run_limits.h"

namespace whitted::cli {
namespace {

using Clock = std::chrono::steady_clock;

// Time a --time-limit keeps for writing the image: encoding runs at tens of megapixels a second on
// this project's 2-core machine (bench/RESULTS.md, PNG encoding); a generous reserve, as a budget
// must not be overrun.
double write_reserve_seconds(int width, int height) { return 0.05 + 50e-9 * double(width) * double(height); }

double budget_of(const RenderSettings& s) {
    return s.time_limit > 0 ? s.time_limit - write_reserve_seconds(s.width, s.height) : 0.0;
}

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

ImageText image_text(const Session& session, const RenderSettings& s) {
    return render_image_text(s, session.samples_done(), session.passes_done(), int(session.pass_ends().size()));
}

}  // namespace

SessionLimits::SessionLimits(const RenderSettings& s, Clock::time_point start)
    : s_(s), start_(start), timeout_(timeout_seconds(s)), budget_(budget_of(s)),
      budget_deadline_(s.time_limit > 0 ? std::max(1e-3, budget_ - seconds_since(start)) : 0.0) {}

const char* SessionLimits::ran_out() const {
    return timeout_.timed_out() ? "--timeout" : budget_deadline_.timed_out() ? "--time-limit" : nullptr;
}

double SessionLimits::seconds_of_limit() const { return timeout_.timed_out() ? timeout_seconds(s_) : s_.time_limit; }

double SessionLimits::elapsed() const { return seconds_since(start_); }

SessionOutcome run_passes(Session& session, const SessionLimits& limits, SessionCheckpoint& checkpoint,
                          const std::function<void(const Tile&, const Film&)>& on_tile) {
    SessionOutcome out;
    while (!session.done()) {
        // A pass that the forecast says would not end within the budget is not begun.
        if (limits.budget() > 0 && session.passes_done() > 0 &&
            limits.elapsed() + session.forecast_next_pass_seconds() > limits.budget()) {
            out.budget_reached = true;
            break;
        }
        out.last = session
                       .render_pass([&](const Tile& t, const Film& film) {
                           checkpoint.tile_done(t, film);
                           if (on_tile) on_tile(t, film);
                       })
                       .render;
        if (out.last.cancelled) break;
        checkpoint.pass_done(session);
    }
    checkpoint.flush();
    out.interrupted = out.last.cancelled && !limits.budget_timed_out();
    // The budget ran out inside a pass: the last whole one stands, as if the forecast had said so.
    out.budget_reached = out.budget_reached || (out.last.cancelled && limits.budget_timed_out() && !limits.timed_out());
    out.complete = !out.interrupted && session.passes_done() > 0 && (session.done() || out.budget_reached);
    return out;
}

std::string write_session_image(const Session& session, const RenderSettings& s, const std::string& path) {
    if (is_linear_output(path)) {
        LinearImage image = session.film().to_linear();
        image.text = image_text(session, s);
        return write_linear_image(image, path);
    }
    Image image = session.film().to_image(view_transform(s));
    image.text = image_text(session, s);
    return write_image(image, path);
}

int write_session(const Session& session, const SessionOutcome& outcome, const RenderOptions& o,
                  const SessionLimits& limits, const char* program, int timeout_code) {
    const RenderSettings& s = o.settings;
    const RenderStats& last = outcome.last;
    const bool complete = outcome.complete;
    // An interrupted render never replaces the output: a good image from an earlier run may be
    // there (a batch timeout's SIGTERM must not destroy it). Its part goes beside it (the last
    // whole pass, or the first pass's tiles if there are some and they can be written quickly).
    if (const std::string why =
            !complete && session.passes_done() == 0 ? why_no_partial_image(last.tiles_done, s.width, s.height) : "";
        !why.empty()) {
        if (limits.ran_out())
            std::cerr << program << ": error: the time limit of " << limits.seconds_of_limit() << " s ("
                      << limits.ran_out() << ") ran out: " << why << ": nothing written\n";
        else
            std::cerr << program << ": interrupted: " << why << ": nothing written\n";
        return limits.ran_out() ? timeout_code : kExitInterrupted;
    }
    const std::string written = complete ? o.output : partial_image_path(o.output);
    // .exr and .pfm keep the linear values; the 8-bit formats get them through the view transform
    // (linear: clamped, §7).
    std::string err;
    if (!s.aov.empty()) {  // the image and its per-term images (session/aov_output.h)
        const std::string aov_file = complete || s.aov_file.empty() ? s.aov_file : partial_image_path(s.aov_file);
        err = write_image_with_aovs(session, written, aov_file, image_text(session, s));
    } else {
        err = write_session_image(session, s, written);
    }
    if (!err.empty()) {
        std::cerr << program << ": error: " << err << "\n";
        return kExitIo;
    }
    const std::string reached = session.passes_done() > 0
                                    ? "the " + std::to_string(session.samples_done()) + " samples per pixel of " +
                                          std::to_string(session.passes_done()) + " whole passes"
                                    : "the " + std::to_string(last.tiles_done) + " of " +
                                          std::to_string(last.tiles_total) + " tiles of the first pass";
    if (complete && outcome.budget_reached) {
        if (!o.quiet)
            std::cerr << "wrote " << o.output << ": " << reached << " fitted in the time limit of " << s.time_limit
                      << " s (" << session.job().sampling.samples_per_pixel() << " asked for)\n";
        return kExitOk;
    }
    if (!complete && limits.ran_out()) {
        std::cerr << program << ": error: the time limit of " << limits.seconds_of_limit() << " s ("
                  << limits.ran_out() << ") ran out: wrote " << reached << " to " << written << " (" << o.output
                  << " was not written)\n";
        return timeout_code;
    }
    if (!complete) {
        std::cerr << program << ": interrupted: wrote " << reached << " to " << written << " (" << o.output
                  << " was not written)\n";
        return kExitInterrupted;
    }
    if (!o.quiet) std::cerr << "wrote " << o.output << "\n";
    return kExitOk;
}

int write_frame(const Session& session, const SessionOutcome& outcome, const RenderOptions& o,
                const SessionLimits& limits, int frame, const char* program, int timeout_code) {
    if (!outcome.complete) {
        std::cerr << program << ": " << (limits.timed_out() ? "error: the time limit (--timeout) ran out" : "interrupted")
                  << " in frame " << frame << ": " << o.output
                  << " not written (run the same command again to go on)\n";
        return limits.timed_out() ? timeout_code : kExitInterrupted;
    }
    if (const std::string err = write_session_image(session, o.settings, o.output); !err.empty()) {
        std::cerr << program << ": error: " << err << "\n";
        return kExitIo;
    }
    if (!o.quiet) std::cerr << "wrote " << o.output << "\n";
    return kExitOk;
}

}  // namespace whitted::cli
