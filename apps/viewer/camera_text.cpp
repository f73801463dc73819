#include "camera_text.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "cs1230/detect.h"

namespace whitted::viewer {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

struct Token {
    std::string_view text;
    std::size_t begin, end;
};

// The format's tokens (scene-format.md §1): whitespace separates them, `[` and `]` are tokens even
// when glued to a word, and a token starting with `#` is a comment to the end of the line.
std::vector<Token> tokenize(std::string_view s) {
    std::vector<Token> out;
    std::size_t i = 0;
    while (i < s.size()) {
        if (is_space(s[i])) {
            ++i;
        } else if (s[i] == '#') {
            while (i < s.size() && s[i] != '\n') ++i;
        } else if (s[i] == '[' || s[i] == ']') {
            out.push_back({s.substr(i, 1), i, i + 1});
            ++i;
        } else {
            const std::size_t b = i;
            while (i < s.size() && !is_space(s[i]) && s[i] != '[' && s[i] != ']') ++i;
            out.push_back({s.substr(b, i - b), b, i});
        }
    }
    return out;
}

// The camera blocks at the top level of the file. `[` is optional in the format (a block opens with
// its keyword), so nesting is counted by the keywords that open blocks and the `]` that close them;
// the word after `mastersubgraph`, `subgraph`, `object` and `texture` is a name, never a keyword.
std::vector<BlockSpan> camera_blocks(std::string_view text, std::string& error) {
    const std::vector<Token> tokens = tokenize(text);
    std::vector<BlockSpan> blocks;
    int depth = 0;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const std::string_view t = tokens[i].text;
        if (t == "]") {
            if (depth > 0) --depth;
        } else if (t == "mastersubgraph" || t == "object") {
            ++i;  // the name or type
            ++depth;
        } else if (t == "subgraph" || t == "texture") {
            ++i;  // a name (texture: its file, then u v, which are numbers)
        } else if (t == "trans" || t == "light" || t == "background") {
            ++depth;
        } else if (t == "camera" && depth == 0) {
            std::size_t j = i + 1;
            while (j < tokens.size() && tokens[j].text != "]") ++j;  // a camera block holds no block
            if (j == tokens.size()) {
                error = "the camera block at byte " + std::to_string(tokens[i].begin) + " is not closed";
                return {};
            }
            blocks.push_back({tokens[i].begin, tokens[j].end});
            i = j;
        }
    }
    return blocks;
}

std::string vec(const glm::vec3& v) {
    return format_number(v.x) + " " + format_number(v.y) + " " + format_number(v.z);
}

}  // namespace

std::string format_number(float value) {
    char buf[64];
    auto r = std::to_chars(buf, buf + sizeof buf, value);
    std::string s(buf, r.ptr);
    // The parser reads a double and rounds it to float: check that this gives the value back,
    // else write the float's exact value as a double (always reads back exactly).
    double back = 0;
    std::from_chars(s.data(), s.data() + s.size(), back);
    if (static_cast<float>(back) != value) {
        r = std::to_chars(buf, buf + sizeof buf, static_cast<double>(value));
        s.assign(buf, r.ptr);
    }
    if (s == "-0") s = "0";  // the same camera; reads better
    return s;
}

std::string camera_block(const CameraDesc& c, bool state_pinhole) {
    std::string s = "camera [ eye " + vec(c.eye);
    if (c.use_focus) s += " focus " + vec(c.focus);
    else s += " look " + vec(c.look);
    s += " up " + vec(c.up) + " angle " + format_number(c.angle_deg);
    if (c.near_plane != CameraDesc{}.near_plane || c.far_plane != CameraDesc{}.far_plane)
        s += " near-far " + format_number(c.near_plane) + " " + format_number(c.far_plane);
    // The distance in focus, stated: the one the renderer uses (make_camera).
    const float fd = c.focal_distance > 0.0f ? c.focal_distance
                     : c.use_focus            ? glm::length(c.focus - c.eye)
                                              : 1.0f;
    if (c.aperture > 0.0f || state_pinhole)
        s += " aperture " + format_number(c.aperture) + " focaldistance " + format_number(fd);
    return s + " ]";
}

CameraReplacement replace_camera_block(std::string_view text, const CameraDesc& camera) {
    CameraReplacement r;
    const std::vector<BlockSpan> blocks = camera_blocks(text, r.error);
    if (!r.error.empty()) return r;
    r.blocks = int(blocks.size());
    // With earlier blocks still in the file, the new one states everything they could set.
    const std::string block = camera_block(camera, blocks.size() > 1);
    if (blocks.empty()) {
        r.text = block + "\n" + std::string(text);
    } else {
        const BlockSpan& last = blocks.back();
        r.text = std::string(text.substr(0, last.begin)) + block + std::string(text.substr(last.end));
    }
    return r;
}

std::string save_camera_into_file(const std::string& path, const CameraDesc& camera) {
    namespace fs = std::filesystem;
    std::ifstream in(path, std::ios::binary);
    if (!in) return "cannot read '" + path + "': " + std::strerror(errno);
    std::ostringstream buf;
    buf << in.rdbuf();
    if (in.bad()) return "cannot read '" + path + "'";
    // A CSCI 1230 JSON file (§9.5) has no camera block to replace: a bracket block would break it.
    if (cs1230::is_json_scene(path, buf.str()))
        return "'" + path + "' is a CSCI 1230 JSON file, whose camera the viewer does not write: set its "
               "cameraData by hand (File > Copy camera gives the eye, focus, up and angle)";
    const CameraReplacement r = replace_camera_block(buf.str(), camera);
    if (!r.error.empty()) return path + ": " + r.error;

    struct stat st{};
    const bool have_mode = ::stat(path.c_str(), &st) == 0;
    const fs::path target(path);
    // A hidden file in the same folder (so the rename stays on one file system).
    std::string name = target.filename().string();
    name.insert(name.begin(), '.');
    name.append(".camera-XXXXXX");
    std::string tmp = (target.parent_path() / name).string();
    const int fd = ::mkstemp(tmp.data());
    if (fd < 0) return "cannot write a temporary file next to '" + path + "': " + std::strerror(errno);
    std::size_t done = 0;
    bool ok = true;
    while (ok && done < r.text.size()) {
        const ssize_t n = ::write(fd, r.text.data() + done, r.text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        ok = n > 0;
        if (ok) done += std::size_t(n);
    }
    const int write_errno = errno;
    if (ok && have_mode) ::fchmod(fd, st.st_mode & 07777);
    ok = ok && ::fsync(fd) == 0;
    ok = (::close(fd) == 0) && ok;
    if (!ok || ::rename(tmp.c_str(), path.c_str()) != 0) {
        const int e = ok ? errno : write_errno;
        ::unlink(tmp.c_str());
        return "cannot write '" + path + "': " + std::strerror(e);
    }
    return "";
}

}  // namespace whitted::viewer
