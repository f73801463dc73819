#include "inspect_command.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "film/image_io.h"
#include "inspect/ray_tree.h"
#include "inspect/report_text.h"
#include "render_options.h"

namespace whitted::cli {
namespace {

// A whole decimal integer (optional '-'), nothing around it.
bool whole_int(std::string_view s, int& out) {
    if (s.empty()) return false;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size();
}

// Written whole or not at all: a temporary file beside the target, renamed over it.
std::string write_text_file(const std::string& path, const std::string& text) {
    const std::filesystem::path target(path);
    std::string tmp = (target.parent_path() / ("." + target.filename().string() + ".XXXXXX")).string();
    const int fd = ::mkstemp(tmp.data());
    if (fd < 0) return "cannot write '" + path + "': " + std::strerror(errno);
    std::size_t done = 0;
    bool ok = true;
    while (ok && done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        ok = n > 0;
        if (ok) done += std::size_t(n);
    }
    const int err = errno;
    const mode_t mask = ::umask(0);  // mkstemp made it 0600: give it the mode a new file gets
    ::umask(mask);
    if (ok) ::fchmod(fd, 0666 & ~mask);
    ok = (::close(fd) == 0) && ok;
    if (!ok || ::rename(tmp.c_str(), path.c_str()) != 0) {
        const int e = ok ? errno : err;
        ::unlink(tmp.c_str());
        return "cannot write '" + path + "': " + std::strerror(e);
    }
    return "";
}

}  // namespace

std::optional<PixelArg> parse_pixel_arg(const std::string& text, int width, int height, std::string& error) {
    const std::size_t comma = text.find(',');
    PixelArg p;
    if (comma == std::string::npos || !whole_int(std::string_view(text).substr(0, comma), p.x) ||
        !whole_int(std::string_view(text).substr(comma + 1), p.y)) {
        error = "--inspect takes a pixel as X,Y (column, row; row 0 at the top), e.g. --inspect 320,240; got '" +
                text + "'";
        return std::nullopt;
    }
    if (p.x < 0 || p.x >= width || p.y < 0 || p.y >= height) {
        error = "--inspect " + text + " is outside the " + std::to_string(width) + "x" + std::to_string(height) +
                " image (columns 0-" + std::to_string(width - 1) + ", rows 0-" + std::to_string(height - 1) + ")";
        return std::nullopt;
    }
    return p;
}

std::string inspect_outputs_problem(const InspectOutputs& outputs) {
    if (outputs.ray_tree_file.empty()) return "";
    const std::string ext = std::filesystem::path(outputs.ray_tree_file).extension().string();
    if (ext != ".obj" && ext != ".json")
        return "--ray-tree writes .obj (polylines) or .json; cannot tell which from '" + outputs.ray_tree_file + "'";
    return output_unwritable(outputs.ray_tree_file);
}

int print_inspection(const Scene& scene, const RenderJob& job, const PixelArg& p, const std::string& scene_path,
                     const InspectOutputs& outputs) {
    const std::string folder = std::filesystem::path(scene_path).parent_path().string();
    const std::string base = folder.empty() ? "." : folder;
    const PixelReport report = inspect_pixel(scene, job, p.x, p.y, job.cancel);
    if (report.cancelled) return kExitInterrupted;  // the caller says why
    if (!outputs.ray_tree_file.empty()) {
        const bool obj = std::filesystem::path(outputs.ray_tree_file).extension() == ".obj";
        const std::string title = "whitted: the ray tree of pixel " + std::to_string(p.x) + "," + std::to_string(p.y) +
                                  " of " + scene_path;
        const std::string text = obj ? ray_tree_obj(report.ray_tree, title) : ray_tree_json(report.ray_tree, p.x, p.y, base);
        if (const std::string err = write_text_file(outputs.ray_tree_file, text); !err.empty()) {
            std::cerr << "whitted: error: " << err << "\n";
            return kExitIo;
        }
    }
    std::cout << (outputs.json ? ray_tree_json(report.ray_tree, p.x, p.y, base) : report_text(report, base));
    std::cout.flush();
    return std::cout ? kExitOk : kExitIo;
}

}  // namespace whitted::cli
