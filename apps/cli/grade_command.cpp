#include "grade_command.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <set>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "compare/colour_map.h"
#include "compare/compare_image.h"
#include "compare/explain.h"
#include "compare/explain_report.h"
#include "compare/grade_report.h"
#include "film/image_io.h"
#include "interrupt.h"
#include "render_options.h"

namespace whitted::cli {
namespace {

namespace fs = std::filesystem;
constexpr const char* kProgram = "whitted grade";

Image to_bytes(const LinearImage& im) {
    Image out(im.width, im.height);
    for (std::size_t i = 0; i < im.rgb.size(); ++i)
        for (int c = 0; c < 3; ++c) out.rgb[i * 3 + c] = to_byte(im.rgb[i][c]);
    return out;
}

// A cell's image file in the report's folder, named by the cell's index, not by the student's or
// the scene's name: any name the file system allows is safe in the page, and no two cells share one.
std::string file_name(std::size_t index, const std::string& what) {
    return "cell" + std::to_string(index) + "." + what + ".png";
}

struct SceneEntry {
    std::string name, path;
};

// The stop of one scene's load and renders: its time limit (--timeout, 60 s under --untrusted) or
// Ctrl-C. Not cli::Deadline, which stops the whole run as a Ctrl-C does: here one slow scene must
// cost its own row only.
class SceneCancel {
public:
    explicit SceneCancel(double seconds)
        : watch_([this, seconds] {
              using clock = std::chrono::steady_clock;
              const auto end = clock::now() + std::chrono::duration_cast<clock::duration>(
                                                  std::chrono::duration<double>(seconds > 0 ? seconds : 1e9));
              std::unique_lock lock(mutex_);
              while (!finished_) {
                  if (interrupt_flag().load()) break;
                  if (clock::now() >= end) {
                      timed_out_ = true;
                      break;
                  }
                  done_.wait_until(lock, std::min(end, clock::now() + std::chrono::milliseconds(20)));
              }
              if (!finished_) stop_ = true;
          }) {}
    ~SceneCancel() {
        {
            std::lock_guard lock(mutex_);
            finished_ = true;
        }
        done_.notify_all();
        watch_.join();
    }
    SceneCancel(const SceneCancel&) = delete;
    SceneCancel& operator=(const SceneCancel&) = delete;
    const std::atomic<bool>* flag() const { return &stop_; }
    bool timed_out() const { return timed_out_; }

private:
    std::mutex mutex_;
    std::condition_variable done_;
    bool finished_ = false;
    std::atomic<bool> stop_{false}, timed_out_{false};
    std::thread watch_;  // last: started once the members it uses are made
};

std::string fmt_seconds(double s);

// A scene being graded: loaded with --untrusted's limits under its own time limit (its load and
// every render of it share it), its first error, and its references rendered so far (one per size,
// and per kind: an 8-bit file's reference is rounded as its bytes are).
struct GradedScene {
    GradedScene(const std::string& scene_path, const RenderOptions& o)
        : path(scene_path), cancel(timeout_seconds(o.settings)),
          time_out("the time limit of " + fmt_seconds(timeout_seconds(o.settings)) +
                   " s (--timeout) ran out rendering this scene") {
        RenderOptions lo = o;
        lo.scene_path = path;
        loaded = load_scene(path, load_options(lo, cancel.flag()));
        if (cancel.timed_out()) {
            problem = time_out;
        } else if (!loaded.ok() && !interrupt_flag().load()) {
            for (const Diagnostic& d : loaded.diagnostics)
                if (d.severity == Severity::Error) {
                    problem = d.str();
                    break;
                }
            if (problem.empty()) problem = path + ": error: the scene could not be loaded";
        }
    }
    std::string path;
    SceneCancel cancel;
    std::string time_out;
    LoadResult loaded;
    std::string problem;  // the load's first error, or the time limit
    std::map<std::tuple<int, int, bool>, LinearImage> references;
};

bool write_thumbnail(const Image& image, const std::string& dir, const std::string& name) {
    if (std::string problem = write_image(image, (fs::path(dir) / name).string()); !problem.empty()) {
        std::cerr << kProgram << ": error: " << problem << "\n";
        return false;
    }
    return true;
}

std::string fmt_seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", s);
    return buf;
}

bool write_text(const std::string& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text;
    return bool(f.flush());
}

int run(int argc, char** argv) {
    CLI::App app{"whitted grade: a class's images against whitted's renders of the reference scenes. SCENES_DIR holds "
                 "the scenes (NAME.sc); SUBMISSIONS_DIR one folder per student holding NAME.png (any format whitted "
                 "reads: NAME.png, .ppm, .bmp, .jpg, .exr, .pfm), and optionally the student's own NAME.sc, which their "
                 "image of that name is then graded against. Each scene is loaded with --untrusted's limits and "
                 "rendered once per size submitted. Writes REPORT_DIR/index.html (a static page: no script, no "
                 "network), report.csv and report.json. docs/compare.md has a worked example.",
                 "whitted grade"};
    app.footer("Exit codes: 0 every image passes, 1 the worst is a WARNING, 2 some image fails or is missing, the "
               "wrong size or unreadable, or its scene would not load; 4 the report cannot be written, 5 bad usage; "
               "130 interrupted.");
    RenderOptions o;
    std::string scenes_dir, submissions_dir, report_dir, explain = "failing";
    ExplainOptions eo;
    app.option_defaults()->always_capture_default();
    app.add_option("scenes", scenes_dir, "The folder of reference scenes (NAME.sc)")->required();
    app.add_option("submissions", submissions_dir, "The folder of students' folders of images (NAME.png)")->required();
    app.add_option("-o,--output", report_dir, "The report's folder (made if missing)")->required()->type_name("DIR");
    app.add_option("--explain", explain, "Which images explain renders the classic mistakes for (about 25 renders each)")
        ->check(CLI::IsMember({"failing", "all", "none"}));
    for (const Setting& setting : render_settings_table()) add_setting_option(app, o.settings, setting);
    auto non_negative = CLI::NonNegativeNumber;
    app.add_option("--fail", eo.compare.thresholds.fail, "A pixel fails if a channel differs by more than this")
        ->check(non_negative);
    app.add_option("--failpercent", eo.compare.thresholds.fail_percent,
                   "FAILURE if more than this percentage of the pixels fail")
        ->check(non_negative);
    app.add_option("--warn", eo.compare.thresholds.warn, "A pixel warns if a channel differs by more than this")
        ->check(non_negative);
    app.add_option("--warnpercent", eo.compare.thresholds.warn_percent,
                   "WARNING if more than this percentage of the pixels warn")
        ->check(non_negative);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kGradePass : kGradeUsage;
    }
    std::error_code ec;
    std::vector<SceneEntry> scenes;
    std::vector<std::string> students;
    if (!fs::is_directory(scenes_dir, ec) || !fs::is_directory(submissions_dir, ec)) {
        std::cerr << kProgram << ": error: " << (fs::is_directory(scenes_dir, ec) ? submissions_dir : scenes_dir)
                  << " is not a folder\n";
        return kGradeUsage;
    }
    for (const fs::directory_entry& e : fs::directory_iterator(scenes_dir, ec))
        if (e.is_regular_file() && e.path().extension() == ".sc")
            scenes.push_back({e.path().stem().string(), e.path().string()});
    for (const fs::directory_entry& e : fs::directory_iterator(submissions_dir, ec))
        if (e.is_directory()) students.push_back(e.path().filename().string());
    std::sort(scenes.begin(), scenes.end(), [](const SceneEntry& a, const SceneEntry& b) { return a.name < b.name; });
    std::sort(students.begin(), students.end());
    if (scenes.empty()) {
        std::cerr << kProgram << ": error: no scene (NAME.sc) in " << scenes_dir << "\n";
        return kGradeUsage;
    }
    // With --width/--height every image must have that size; without, each is graded at its own.
    const bool sized = app.get_option("--width")->count() > 0 || app.get_option("--height")->count() > 0;
    const int want_w = o.settings.width, want_h = o.settings.height;
    // Every scene a student's class hands around is treated as untrusted: the limits of --untrusted.
    o.settings.untrusted = true;
    o.settings.given.insert("untrusted");
    o.scene_path = scenes.front().path;
    o.output = (fs::path(report_dir) / "reference.png").string();  // checked as the renderer checks -o
    if (std::string problem = finish_render_options(app, o, Frontend::Cli); !problem.empty()) {
        std::cerr << kProgram << ": error: " << problem << "\n";
        return kGradeUsage;
    }
    fs::create_directories(report_dir, ec);
    if (!fs::is_directory(report_dir)) {
        std::cerr << kProgram << ": error: cannot make the folder " << report_dir << "\n";
        return kGradeFile;
    }
    install_interrupt_handler();
    GradeReport report;
    // Students' own scene files: NAME.sc beside their NAME.png. A class scene's name: their image is
    // of their scene, which the reference is rendered from; any other name: a row of its own.
    std::map<std::string, std::set<std::string>> own;  // by student
    std::vector<std::string> own_rows;
    for (const std::string& student : students)
        for (const fs::directory_entry& e : fs::directory_iterator(fs::path(submissions_dir) / student, ec))
            if (e.is_regular_file() && e.path().extension() == ".sc") {
                const std::string name = e.path().stem().string();
                own[student].insert(name);
                if (std::none_of(scenes.begin(), scenes.end(), [&](const SceneEntry& s) { return s.name == name; }) &&
                    std::find(own_rows.begin(), own_rows.end(), name) == own_rows.end())
                    own_rows.push_back(name);
            }
    std::sort(own_rows.begin(), own_rows.end());
    for (const SceneEntry& s : scenes) report.scenes.push_back(s.name);
    for (const std::string& name : own_rows) {
        report.scenes.push_back(name);
        scenes.push_back({name, ""});  // no class scene
    }
    report.students = students;
    const char* kFormats[] = {".png", ".ppm", ".bmp", ".jpg", ".jpeg", ".tga", ".exr", ".pfm"};
    for (const SceneEntry& s : scenes) {
        // The class's scene, loaded once for its row when a student needs it: its load and every
        // render of it share its time limit.
        std::unique_ptr<GradedScene> class_scene;
        for (const std::string& student : students) {
            if (interrupt_flag().load()) {
                std::cerr << kProgram << ": interrupted\n";
                return kExitInterrupted;
            }
            const std::size_t index = report.cells.size();
            GradeCell c;
            c.scene = s.name;
            c.student = student;
            // A student's own scene is loaded as any file from others is (--untrusted: files only
            // from their folder), with a time limit of its own.
            std::unique_ptr<GradedScene> own_scene;
            GradedScene* scene = nullptr;
            if (own[student].count(s.name)) {
                c.scene_file = s.name + ".sc";
                own_scene = std::make_unique<GradedScene>(
                    (fs::path(submissions_dir) / student / c.scene_file).string(), o);
                scene = own_scene.get();
            } else if (!s.path.empty()) {
                if (!class_scene) class_scene = std::make_unique<GradedScene>(s.path, o);
                scene = class_scene.get();
            } else {
                c.status = CellStatus::not_theirs;
                report.cells.push_back(std::move(c));
                continue;
            }
            if (scene->cancel.timed_out()) scene->problem = scene->time_out;
            std::string image_path;
            for (const char* ext : kFormats) {
                const fs::path p = fs::path(submissions_dir) / student / (s.name + ext);
                if (fs::is_regular_file(p, ec)) {
                    image_path = p.string();
                    break;
                }
            }
            CompareImage image;
            if (image_path.empty()) {
                c.status = CellStatus::missing;
                c.problem = "no " + s.name + ".png";
            } else if (std::string problem = read_compare_image(image_path, image); !problem.empty()) {
                c.status = CellStatus::unreadable;
                c.problem = problem;
            } else if (!scene->problem.empty()) {
                c.status = scene->cancel.timed_out() ? CellStatus::timed_out : CellStatus::scene_error;
                c.problem = scene->problem;
            }
            if (!image_path.empty() && c.problem.empty()) {
                c.image_file = file_name(index, "image");
                if (!write_thumbnail(to_bytes(image.pixels), report_dir, c.image_file)) return kGradeFile;
            }
            if (!c.problem.empty()) {
                report.cells.push_back(std::move(c));
                continue;
            }
            if (sized && (image.pixels.width != want_w || image.pixels.height != want_h)) {
                c.status = CellStatus::wrong_size;
                c.problem = std::to_string(image.pixels.width) + "x" + std::to_string(image.pixels.height) + ", not " +
                            std::to_string(want_w) + "x" + std::to_string(want_h);
                report.cells.push_back(std::move(c));
                continue;
            }
            RenderOptions so = o;
            so.scene_path = scene->path;
            so.settings.width = image.pixels.width;
            so.settings.height = image.pixels.height;
            so.settings.given.insert("width");
            so.settings.given.insert("height");
            if (std::string problem = validate(so.settings); !problem.empty()) {
                c.status = CellStatus::wrong_size;
                c.problem = problem;
                report.cells.push_back(std::move(c));
                continue;
            }
            RenderJob job = render_job(so, scene->cancel.flag());
            const auto size = std::make_tuple(image.pixels.width, image.pixels.height, image.linear);
            auto it = scene->references.find(size);
            if (it == scene->references.end()) {
                LinearImage rendered = render_variant(*scene->loaded.scene, job, nullptr, !image.linear);
                if (scene->cancel.flag()->load()) {  // stopped part way: not a reference
                    if (interrupt_flag().load()) continue;  // said at the top of the loop
                    scene->problem = scene->time_out;
                    c.status = CellStatus::timed_out;
                    c.problem = scene->time_out;
                    report.cells.push_back(std::move(c));
                    continue;
                }
                it = scene->references.emplace(size, std::move(rendered)).first;
            }
            const LinearImage& reference = it->second;
            c.reference_file = file_name(index, "reference");
            if (!write_thumbnail(to_bytes(reference), report_dir, c.reference_file)) return kGradeFile;
            const CompareReport r = compare_images(reference, image.pixels, eo.compare);
            c.status = CellStatus::compared;
            c.verdict = r.verdict;
            c.psnr = r.errors.psnr;
            c.flip_mean = r.flip.mean;
            c.ssim_worst = r.ssim.worst.ssim;
            if (r.verdict != Verdict::pass) {
                c.error_file = file_name(index, "error");
                if (!write_thumbnail(magma_image(r.flip.error, r.width, r.height), report_dir, c.error_file))
                    return kGradeFile;
            }
            if (explain == "all" || (explain == "failing" && r.verdict == Verdict::fail)) {
                ExplainOptions x = eo;
                x.quantize = !image.linear;
                x.cancel = scene->cancel.flag();
                const Explanation e = explain_image(*scene->loaded.scene, job, image.pixels, x);
                c.explanation = e.cancelled || scene->cancel.flag()->load()
                                    ? std::string("not explained: the scene's time limit ran out")
                                    : explain_summary(e);
            }
            report.cells.push_back(std::move(c));
        }
    }
    const fs::path dir(report_dir);
    if (!write_text((dir / "index.html").string(), grade_html(report)) ||
        !write_text((dir / "report.csv").string(), grade_csv(report)) ||
        !write_text((dir / "report.json").string(), grade_json(report))) {
        std::cerr << kProgram << ": error: cannot write the report in " << report_dir << "\n";
        return kGradeFile;
    }
    const int code = grade_exit_code(report);
    std::cout << kProgram << ": " << report.scenes.size() << " scenes x " << report.students.size()
              << " students: " << (dir / "index.html").string() << " ("
              << (code == 0 ? "all pass" : code == 1 ? "some warn" : "some fail") << ")\n";
    return code;
}

}  // namespace

int grade_main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::cerr << kProgram << ": error: out of memory\n";
    } catch (const std::exception& e) {
        std::cerr << kProgram << ": error: " << e.what() << "\n";
    }
    return kGradeFile;
}

}  // namespace whitted::cli
