#include "compare_command.h"

#include <csignal>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>

#include <CLI/CLI.hpp>
#include <unistd.h>

#include "compare/colour_map.h"
#include "compare/compare.h"
#include "compare/compare_image.h"
#include "compare/report.h"
#include "film/image_io.h"

namespace whitted::cli {
namespace {

constexpr const char* kProgram = "whitted compare";

// Ctrl-C, SIGTERM, SIGHUP, SIGQUIT: stop at once (exit 130), removing the --diff image's temporary
// file if it is being written (the image itself is only ever renamed into place whole).
extern "C" void on_signal(int) {
    if (const char* partial = image_file_being_written()) unlink(partial);
    _exit(130);
}

void install_signal_handlers() {
    struct sigaction sa {};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaction(sig, &sa, nullptr);
}

// True if `a` and `b` name the same existing file.
bool same_file(const std::string& a, const std::string& b) {
    std::error_code ec;
    return std::filesystem::equivalent(a, b, ec) && !ec;
}

int run(int argc, char** argv) {
    CLI::App app{"whitted compare: how far image B is from the reference image A. PSNR, mean and max error and the "
                 "pixels over a tolerance as OpenImageIO's idiff computes them (with its thresholds and exit codes), "
                 "SSIM over 8x8 blocks (SPEC CPU's povray check) and FLIP (Andersson et al. 2020). docs/compare.md "
                 "says what each means and what to do about a difference.",
                 "whitted compare"};
    app.footer("Exit codes (idiff's): 0 PASS, 1 WARNING, 2 FAILURE, 3 the images differ in size, 4 an image cannot "
               "be read or the --diff image written; 5 bad usage; 130 interrupted.");
    std::string path_a, path_b, diff_path;
    CompareOptions o;
    bool json = false, quiet = false;
    app.add_option("A", path_a, "The reference image (PNG, JPEG, BMP, TGA, PPM, OpenEXR or PFM)")->required();
    app.add_option("B", path_b, "The image to compare with it, of the same size")->required();
    auto non_negative = CLI::NonNegativeNumber;
    app.add_option("--fail", o.thresholds.fail, "A pixel fails if a channel differs by more than this (default 1e-6)")
        ->check(non_negative);
    app.add_option("--failpercent", o.thresholds.fail_percent,
                   "FAILURE if more than this percentage of the pixels fail (default 0)")
        ->check(non_negative);
    app.add_option("--hardfail", o.thresholds.hard_fail, "FAILURE if any channel differs by more than this (default: none)")
        ->check(non_negative);
    app.add_option("--warn", o.thresholds.warn, "A pixel warns if a channel differs by more than this (default 1e-6)")
        ->check(non_negative);
    app.add_option("--warnpercent", o.thresholds.warn_percent,
                   "WARNING if more than this percentage of the pixels warn (default 0)")
        ->check(non_negative);
    app.add_option("--hardwarn", o.thresholds.hard_warn, "WARNING if any channel differs by more than this (default: none)")
        ->check(non_negative);
    app.add_option("--ssim-threshold", o.ssim.threshold,
                   "Count the 8x8 blocks whose SSIM is at or below this (default 0.996, SPEC's)")
        ->check(CLI::Range(-1.0, 1.0));
    app.add_option("--ppd", o.flip.pixels_per_degree,
                   "FLIP's viewing distance as pixels per degree of visual angle (default 67.02: a 0.7 m wide "
                   "3840-pixel screen seen from 0.7 m)")
        ->check(CLI::Range(1.0, 1000.0));
    app.add_option("--diff", diff_path,
                   "Write FLIP's error image (magma colours: black, no difference, to pale yellow, the largest) "
                   "to FILE; the extension picks the format")
        ->type_name("FILE");
    app.add_flag("--json", json, "Print one JSON object with every metric instead of the text report");
    app.add_flag("-q,--quiet", quiet, "Print nothing but errors: the exit code says it");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kComparePass : kCompareUsage;
    }
    install_signal_handlers();
    if (!diff_path.empty()) {
        if (same_file(diff_path, path_a) || same_file(diff_path, path_b)) {
            std::cerr << kProgram << ": error: --diff " << diff_path << " would replace an image being compared\n";
            return kCompareUsage;
        }
        if (std::string problem = output_problem(1, 1, diff_path); !problem.empty()) {
            std::cerr << kProgram << ": error: " << problem << "\n";
            return kCompareUsage;
        }
        if (std::string problem = output_unwritable(diff_path); !problem.empty()) {
            std::cerr << kProgram << ": error: " << problem << "\n";
            return kCompareFile;
        }
    }

    CompareImage a, b;
    for (auto [path, image] : {std::pair{&path_a, &a}, std::pair{&path_b, &b}})
        if (std::string problem = read_compare_image(*path, *image); !problem.empty()) {
            std::cerr << kProgram << ": error: " << problem << "\n";
            return kCompareFile;
        }
    if (std::string problem = compare_problem(a.pixels, b.pixels); !problem.empty()) {
        std::cerr << kProgram << ": error: " << problem << " ('" << path_a << "' and '" << path_b << "')\n";
        return kCompareSize;
    }

    const CompareReport report = compare_images(a.pixels, b.pixels, o);
    if (!diff_path.empty()) {
        if (std::string problem = write_image(magma_image(report.flip.error, report.width, report.height), diff_path);
            !problem.empty()) {
            std::cerr << kProgram << ": error: " << problem << "\n";
            return kCompareFile;
        }
    }
    const CompareInputs inputs{path_a, a.format, path_b, b.format, diff_path};
    if (!quiet) std::cout << (json ? report_json(inputs, o, report) : report_text(inputs, o, report)) << std::flush;
    return int(report.verdict);
}

}  // namespace

int compare_main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::cerr << kProgram << ": error: out of memory (the images are too large to compare here)\n";
    } catch (const std::exception& e) {
        std::cerr << kProgram << ": error: " << e.what() << "\n";
    }
    return kCompareFile;
}

}  // namespace whitted::cli
