// parse_bench: how fast scene text becomes a SceneDescription, one thread, the file already in
// memory (the read is the disk's business, not the parser's).
//
//   parse_bench [--runs N] FILE...
//
// Per file: the median and best of N parses (default 5) in seconds and MB/s (10^6 bytes), and a
// summary of what came out (diagnostics, subgraphs, trans blocks, objects), so that two builds
// compared side by side (bench/compare_parse.sh) can be seen to read the same scene.
// Only parser.h is used, so the same source builds against an older tree.
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

std::string read_all(const char* path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "parse_bench: cannot read %s\n", path);
        std::exit(1);
    }
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 5;
    std::vector<const char*> files;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else
            files.push_back(argv[i]);
    }
    if (files.empty()) {
        std::fprintf(stderr, "usage: parse_bench [--runs N] FILE...\n");
        return 1;
    }
    for (const char* path : files) {
        const std::string text = read_all(path);
        std::vector<double> seconds;
        std::size_t diagnostics = 0, subgraphs = 0, trans = 0, objects = 0;
        for (int r = 0; r < runs; ++r) {
            const auto t0 = Clock::now();
            const whitted::ParseResult result = whitted::parse_scene_text(text, path);
            seconds.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
            diagnostics = result.diagnostics.size();
            subgraphs = result.scene.subgraphs.size();
            trans = objects = 0;
            for (const auto& sg : result.scene.subgraphs)
                for (const auto& t : sg.children) ++trans, objects += t.objects.size();
        }
        std::sort(seconds.begin(), seconds.end());
        const double median = seconds[seconds.size() / 2], best = seconds.front();
        const double mb = double(text.size()) * 1e-6;
        std::printf("%s: %.2f MB, median %.4f s (%.1f MB/s), best %.4f s (%.1f MB/s), %d runs; "
                    "%zu diagnostics, %zu subgraphs, %zu trans, %zu objects\n",
                    path, mb, median, mb / median, best, mb / best, runs, diagnostics, subgraphs, trans, objects);
    }
    return 0;
}
