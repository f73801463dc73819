// parse_bench: how fast scene text becomes a SceneDescription, one thread, the file already in
// memory (the read is the disk's business, not the parser's).
//
//   parse_bench [--runs N] FILE...
//   parse_bench --dump [--lenient] FILE...
//
// Per file: the median and best of N parses (default 5) in seconds and MB/s (10^6 bytes), of the
// wall clock and of the thread's CPU time (on a shared machine the thread also waits for a core,
// which the CPU time leaves out), the median of its user time alone, and a summary of what came
// out (diagnostics, subgraphs, trans blocks, objects), so that two builds compared side by side
// (bench/compare_parse.sh) can be seen to read the same scene.
// --dump prints everything the parse gave instead (every diagnostic, every field of the
// description, floats in hex): two builds that read the same files print the same bytes.
// Only parser.h is used, so the same source builds against an older tree.
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "parse/parser.h"

namespace {

using Clock = std::chrono::steady_clock;

// User time alone (the parser's own work; system time is mostly the page faults of the memory the
// description is written into), from the kernel's split of the thread's run time.
double thread_user_seconds() {
    rusage u{};
    getrusage(RUSAGE_THREAD, &u);
    return double(u.ru_utime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec);
}

double thread_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

std::string read_all(const char* path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "parse_bench: cannot read %s\n", path);
        std::exit(1);
    }
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string hex(float v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", double(v));
    return buf;
}
std::string hex(const glm::vec3& v) { return hex(v.x) + " " + hex(v.y) + " " + hex(v.z); }
std::string at(const whitted::SourceLoc& l) {
    return l.file + ":" + std::to_string(l.line) + ":" + std::to_string(l.col);
}

// Diagnostics as the command line prints them: every error, the first 50 warnings, a count of the
// rest (newer parsers keep only those and count the rest themselves).
template <class Result>
void dump(const Result& r) {
    using std::printf;
    std::size_t warnings = 0;
    for (const auto& d : r.diagnostics)
        if (d.severity == whitted::Severity::Error || ++warnings <= 50) printf("diagnostic %s\n", d.str().c_str());
    if constexpr (requires { r.unlisted_warnings; }) warnings += r.unlisted_warnings;
    if (warnings > 50) printf("%zu more warnings\n", warnings - 50);
    printf("ok %d unreadable %d cancelled %d\n", r.ok(), r.unreadable, r.cancelled);
    const whitted::SceneDescription& s = r.scene;
    printf("path %s dialect %d root %d background %s ambient %s\n", s.path.c_str(), int(s.dialect), s.root,
           hex(s.background).c_str(), hex(s.ambient_intensity).c_str());
    const whitted::CameraDesc& c = s.camera;
    printf("camera %s eye %s look %s focus %s use_focus %d up %s angle %s near %s far %s aperture %s focal %s\n",
           at(c.loc).c_str(), hex(c.eye).c_str(), hex(c.look).c_str(), hex(c.focus).c_str(), c.use_focus,
           hex(c.up).c_str(), hex(c.angle_deg).c_str(), hex(c.near_plane).c_str(), hex(c.far_plane).c_str(),
           hex(c.aperture).c_str(), hex(c.focal_distance).c_str());
    for (const auto& l : s.lights)
        printf("light %s type %d position %s direction %s color %s falloff %s aperture %s exponent %s radius %s "
               "angle %s\n",
               at(l.loc).c_str(), int(l.type), hex(l.position).c_str(), hex(l.direction).c_str(),
               hex(l.color).c_str(), hex(l.falloff).c_str(), hex(l.aperture_deg).c_str(), hex(l.exponent).c_str(),
               hex(l.radius).c_str(), hex(l.angle_deg).c_str());
    for (const auto& sg : s.subgraphs) {
        printf("subgraph %s %s implicit %d\n", sg.name.c_str(), at(sg.loc).c_str(), sg.implicit);
        for (const auto& t : sg.children) {
            printf(" trans %s", at(t.loc).c_str());
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) printf(" %s", hex(t.matrix[i][j]).c_str());
            printf("\n");
            for (const auto& ref : t.subgraphs) printf("  subgraph %s %s\n", ref.name.c_str(), at(ref.loc).c_str());
            for (const auto& o : t.objects) {
                const whitted::MaterialDesc& m = o.material;
                printf("  object %s kind %d mesh '%s' %s ambient %s diffuse %s specular %s reflect %s transparent %s "
                       "emit %s shine %s ior %s gloss %s blend %s\n",
                       at(o.loc).c_str(), int(o.kind), o.mesh_file.c_str(), at(o.mesh_loc).c_str(),
                       hex(m.ambient).c_str(), hex(m.diffuse).c_str(), hex(m.specular).c_str(), hex(m.reflect).c_str(),
                       hex(m.transparent).c_str(), hex(m.emit).c_str(), hex(m.shine).c_str(), hex(m.ior).c_str(),
                       hex(m.gloss).c_str(), m.blend ? hex(*m.blend).c_str() : "-");
                if (m.texture)
                    printf("   texture '%s' %s %s %s loose %d\n", m.texture->file.c_str(), hex(m.texture->repeat_u).c_str(),
                           hex(m.texture->repeat_v).c_str(), at(m.texture->loc).c_str(), m.texture->loose_lookup);
            }
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 5;
    bool dumping = false, lenient = false;
    std::vector<const char*> files;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else if (a == "--dump")
            dumping = true;
        else if (a == "--lenient")
            lenient = true;
        else
            files.push_back(argv[i]);
    }
    if (files.empty()) {
        std::fprintf(stderr, "usage: parse_bench [--runs N] FILE... | --dump [--lenient] FILE...\n");
        return 1;
    }
    if (dumping) {
        whitted::ParseOptions options;
        options.lenient = lenient;
        for (const char* path : files) {
            std::printf("== %s\n", path);
            dump(whitted::parse_scene_text(read_all(path), path, options));
        }
        return 0;
    }
    for (const char* path : files) {
        const std::string text = read_all(path);
        std::vector<double> seconds, cpu_seconds, user_seconds;
        std::size_t diagnostics = 0, subgraphs = 0, trans = 0, objects = 0;
        for (int r = 0; r < runs; ++r) {
            const auto t0 = Clock::now();
            const double c0 = thread_cpu_seconds(), u0 = thread_user_seconds();
            const whitted::ParseResult result = whitted::parse_scene_text(text, path);
            cpu_seconds.push_back(thread_cpu_seconds() - c0);
            user_seconds.push_back(thread_user_seconds() - u0);
            seconds.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
            diagnostics = result.diagnostics.size();
            subgraphs = result.scene.subgraphs.size();
            trans = objects = 0;
            for (const auto& sg : result.scene.subgraphs)
                for (const auto& t : sg.children) ++trans, objects += t.objects.size();
        }
        std::sort(seconds.begin(), seconds.end());
        std::sort(cpu_seconds.begin(), cpu_seconds.end());
        std::sort(user_seconds.begin(), user_seconds.end());
        const double user_median = user_seconds[user_seconds.size() / 2];
        const double median = seconds[seconds.size() / 2], best = seconds.front();
        const double cpu_median = cpu_seconds[cpu_seconds.size() / 2], cpu_best = cpu_seconds.front();
        const double mb = double(text.size()) * 1e-6;
        std::printf("%s: %.2f MB, %d runs; wall: median %.4f s (%.1f MB/s), best %.4f s (%.1f MB/s); "
                    "cpu: median %.4f s (%.1f MB/s), best %.4f s (%.1f MB/s); "
                    "user: median %.4f s (%.1f MB/s); %zu diagnostics, %zu subgraphs, %zu trans, %zu objects\n",
                    path, mb, runs, median, mb / median, best, mb / best, cpu_median, mb / cpu_median, cpu_best,
                    mb / cpu_best, user_median, user_median > 0 ? mb / user_median : 0.0, diagnostics, subgraphs,
                    trans, objects);
    }
    return 0;
}
