// The viewer's moving-camera render path: how soon the first coarse frame follows a
// camera change, and how many coarse frames a second a drag gets. Drives the viewer's
// RenderController exactly as the window does (no display). Build with -DWHITTED_BUILD_BENCH=ON in
// Release; run: build/bench/viewer_nav_bench [SCENE] [WIDTH HEIGHT THREADS]
// (default scenes/showcase.sc 1000 637 2). The machine's load average is printed with the
// numbers: on a shared machine they vary with it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "camera_navigation.h"
#include "flatten/flatten.h"
#include "render_controller.h"

using namespace whitted;
using namespace whitted::viewer;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

namespace {

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

}  // namespace

int main(int argc, char** argv) {
    const std::string scene = argc > 1 ? argv[1] : std::string(WHITTED_SOURCE_DIR) + "/scenes/showcase.sc";
    RenderJob job;
    job.width = argc > 3 ? std::atoi(argv[2]) : 1000;
    job.height = argc > 3 ? std::atoi(argv[3]) : 637;
    job.threads = argc > 4 ? std::atoi(argv[4]) : 2;
    LoadOptions load;
    load.threads = job.threads;
    load.textures.missing = MissingTexturePolicy::Checker;
    std::printf("scene %s, %dx%d, %d threads; load average before: %s\n", scene.c_str(), job.width, job.height,
                job.threads, load_average().c_str());

    RenderController c;
    c.start(scene, load, job);  // loads (and renders) once; camera moves reuse the loaded scene
    if (!c.wait(120s) || c.status().state != RenderState::Finished) {
        std::fprintf(stderr, "the scene did not render: %s\n", c.status().message.c_str());
        return 1;
    }
    const CameraDesc start = navigable(c.status().file_camera);

    // 1. Latency: a camera change on an idle controller, until the first (1/8) frame is there.
    std::vector<double> latency;
    for (int i = 1; i <= 40; ++i) {
        RenderJob moved = job;
        moved.camera = make_camera(orbit(start, float(i * 7), float(i % 5)));
        const auto t0 = Clock::now();
        c.start(scene, load, moved, false, true);
        while (c.status().frames == 0 && Clock::now() - t0 < 5s) std::this_thread::sleep_for(50us);
        latency.push_back(ms(Clock::now() - t0));
        c.stop();
        c.wait_all_threads(10s);
    }
    std::sort(latency.begin(), latency.end());
    std::printf("camera change -> first coarse frame (1/8 resolution), 40 changes: median %.1f ms, 90%% %.1f ms, "
                "max %.1f ms\n",
                latency[latency.size() / 2], latency[latency.size() * 9 / 10], latency.back());

    // 2. A drag: a new camera every 16.7 ms (a 60 Hz mouse) for 3 s, each cancelling the frame
    // before; the UI's view: how many coarse frames a second reach the screen, and of which size.
    int frames = 0, by_divisor[9] = {};
    std::uint64_t last_job = 0, last_frames = 0;
    const auto t0 = Clock::now();
    auto next_event = t0;
    int events = 0;
    while (Clock::now() - t0 < 3s) {
        if (Clock::now() >= next_event) {
            RenderJob moved = job;
            moved.camera = make_camera(orbit(start, float(events) * 2.0f, 0));
            c.start(scene, load, moved, false, true);
            ++events;
            next_event += std::chrono::microseconds(16667);
        }
        const RenderStatus st = c.status();
        if (st.job != last_job) last_job = st.job, last_frames = 0;
        if (st.frames > last_frames) {
            frames += int(st.frames - last_frames);
            by_divisor[std::clamp(st.preview_divisor, 0, 8)] += int(st.frames - last_frames);
            last_frames = st.frames;
        }
        std::this_thread::sleep_for(200us);
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    std::printf("drag, %d camera events in %.2f s: %.1f coarse frames/s (by size: 1/8: %d, 1/4: %d, "
                "1/2: %d)\n",
                events, seconds, frames / seconds, by_divisor[8], by_divisor[4], by_divisor[2]);
    c.stop();
    c.wait_all_threads(10s);
    std::printf("load average after: %s\n", load_average().c_str());
    return 0;
}
