#include "camera_text.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <vector>

#include "base/file_replace.h"
#include "base/read_file.h"

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

namespace {

// Writes all of `text` to `fd`; false (errno set) if it could not.
bool write_all(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += std::size_t(n);
    }
    return true;
}

}  // namespace

std::string save_camera_into_file(const std::string& path, const CameraDesc& camera) {
    namespace fs = std::filesystem;
    const FileContents file = read_regular_file(path, std::size_t(256) << 20);
    if (!file.ok()) return "cannot read '" + path + "': " + file.error;
    const CameraReplacement r = replace_camera_block(file.bytes, camera);
    if (!r.error.empty()) return path + ": " + r.error;

    // The file a link leads to is the scene (the link stays); the new text keeps its permissions.
    const ReplaceTarget target = replace_target(path);
    const fs::path real(target.path);
    // A hidden file in the same folder (so the rename stays on one file system).
    std::string name = real.filename().string();
    name.insert(name.begin(), '.');
    name.append(".camera-XXXXXX");
    std::string tmp = (real.parent_path() / name).string();
    const int fd = ::mkstemp(tmp.data());
    if (fd < 0) return "cannot write a temporary file next to '" + target.path + "': " + std::strerror(errno);
    keep_permissions(fd, target);
    bool ok = write_all(fd, r.text) && ::fsync(fd) == 0;
    int error = errno;
    ok = (::close(fd) == 0) && ok;
    if (!ok) {
        ::unlink(tmp.c_str());
        return "cannot write '" + path + "': " + std::strerror(error);
    }
    if (target.links <= 1) {
        if (::rename(tmp.c_str(), target.path.c_str()) != 0) {
            error = errno;
            ::unlink(tmp.c_str());
            return "cannot write '" + path + "': " + std::strerror(error);
        }
        return "";
    }
    // Hard links: a rename would leave the other names the old scene. The file itself is rewritten,
    // now that the new text is safe beside it (kept there if this fails half-way).
    const int out = ::open(target.path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    ok = out >= 0 && write_all(out, r.text) && ::fsync(out) == 0;
    error = errno;
    if (out >= 0) ok = (::close(out) == 0) && ok;
    if (!ok) return "cannot write '" + path + "': " + std::strerror(error) + " (the new text is in '" + tmp + "')";
    ::unlink(tmp.c_str());
    return "";
}

}  // namespace whitted::viewer
