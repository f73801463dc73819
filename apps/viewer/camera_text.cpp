#include "camera_text.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <optional>
#include <vector>

#include "base/file_replace.h"
#include "base/read_file.h"
#include "cs1230/detect.h"
#include "flatten/flatten.h"
#include "parse/number.h"

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

// The camera blocks at the top level of the file, as the indices of their `camera` and `]` tokens.
// `[` is optional in the format (a block opens with its keyword), so nesting is counted by the
// keywords that open blocks and the `]` that close them; the word after `mastersubgraph`,
// `subgraph`, `object` and `texture` is a name, never a keyword.
struct BlockTokens {
    std::size_t first, last;
};

std::vector<BlockTokens> camera_blocks(const std::vector<Token>& tokens, std::string& error) {
    std::vector<BlockTokens> blocks;
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
            blocks.push_back({i, j});
            i = j;
        }
    }
    return blocks;
}

// The camera keywords and how many numbers each takes (scene-format.md §5, §9.1).
enum class Key { Eye, Look, Focus, Up, Angle, NearFar, Aperture, FocalDistance };
constexpr std::pair<std::string_view, int> kKeys[] = {{"eye", 3},   {"look", 3},     {"focus", 3},    {"up", 3},
                                                      {"angle", 1}, {"near-far", 2}, {"aperture", 1}, {"focaldistance", 1}};

// A keyword in a camera block: its token and its numbers (as read).
struct Occurrence {
    Key key;
    std::size_t token;  // the keyword's; its numbers are the tokens after it
    float v[3];
};

// The keywords of the block between tokens `first` (`camera`) and `last` (`]`), in order. False
// when one lacks its numbers (a file that did not load).
bool read_block(const std::vector<Token>& tokens, const BlockTokens& b, std::vector<Occurrence>& out) {
    for (std::size_t i = b.first + 1; i < b.last; ++i) {
        const auto k = std::find_if(std::begin(kKeys), std::end(kKeys), [&](const auto& e) { return e.first == tokens[i].text; });
        if (k == std::end(kKeys)) continue;  // `[`, or a word a lenient load skipped
        Occurrence o{Key(k - std::begin(kKeys)), i, {0, 0, 0}};
        for (int n = 0; n < k->second; ++n) {
            if (i + 1 + std::size_t(n) >= b.last) return false;
            const NumberParse p = parse_number(tokens[i + 1 + std::size_t(n)].text);
            if (p.status != NumberStatus::Ok && p.status != NumberStatus::TrailingComma) return false;
            o.v[n] = p.value;
        }
        out.push_back(o);
        i += std::size_t(k->second);
    }
    return true;
}

// A block's keywords applied to a camera, as the parser does.
void apply_block(const std::vector<Occurrence>& block, CameraDesc& c) {
    for (const Occurrence& o : block) {
        const glm::vec3 v(o.v[0], o.v[1], o.v[2]);
        switch (o.key) {
            case Key::Eye: c.eye = v; break;
            case Key::Look: c.look = v, c.use_focus = false; break;
            case Key::Focus: c.focus = v, c.use_focus = true; break;
            case Key::Up: c.up = v; break;
            case Key::Angle: c.angle_deg = o.v[0]; break;
            case Key::NearFar: c.near_plane = o.v[0], c.far_plane = o.v[1]; break;
            case Key::Aperture: c.aperture = o.v[0]; break;
            case Key::FocalDistance: c.focal_distance = o.v[0]; break;
        }
    }
}

// The camera of every camera block of `text` merged, or none when it cannot be read.
std::optional<CameraDesc> merged_camera(std::string_view text) {
    const std::vector<Token> tokens = tokenize(text);
    std::string error;
    CameraDesc c;
    for (const BlockTokens& b : camera_blocks(tokens, error)) {
        std::vector<Occurrence> block;
        if (!read_block(tokens, b, block)) return std::nullopt;
        apply_block(block, c);
    }
    if (!error.empty()) return std::nullopt;
    return c;
}

// Whether two cameras give the same image: the renderer's cameras are equal (the distance in focus
// matters only through a lens).
bool same_image(const CameraDesc& a, const CameraDesc& b) {
    const Camera ca = make_camera(a), cb = make_camera(b);
    return ca.eye == cb.eye && ca.forward == cb.forward && ca.right == cb.right && ca.up == cb.up &&
           ca.tan_half_fov == cb.tan_half_fov && ca.lens_radius == cb.lens_radius &&
           (ca.is_pinhole() || ca.focal_distance == cb.focal_distance);
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

namespace {

// The distance in focus the renderer uses (make_camera), stated in a block.
float focal_distance_of(const CameraDesc& c) { return make_camera(c).focal_distance; }

// The numbers a keyword takes for `c`.
std::string values_of(Key key, const CameraDesc& c) {
    switch (key) {
        case Key::Eye: return vec(c.eye);
        case Key::Look: return vec(c.look);
        case Key::Focus: return vec(c.focus);
        case Key::Up: return vec(c.up);
        case Key::Angle: return format_number(c.angle_deg);
        case Key::NearFar: return format_number(c.near_plane) + " " + format_number(c.far_plane);
        case Key::Aperture: return format_number(c.aperture);
        case Key::FocalDistance: return format_number(focal_distance_of(c));
    }
    return "";
}

// Whether keyword `key`'s numbers as read (`o`) already say what `c` needs.
bool holds(const Occurrence& o, const CameraDesc& c) {
    const glm::vec3 v(o.v[0], o.v[1], o.v[2]);
    switch (o.key) {
        case Key::Eye: return v == c.eye;
        case Key::Look: return v == c.look;
        case Key::Focus: return v == c.focus;
        case Key::Up: return v == c.up;
        case Key::Angle: return o.v[0] == c.angle_deg;
        case Key::NearFar: return o.v[0] == c.near_plane && o.v[1] == c.far_plane;
        case Key::Aperture: return o.v[0] == c.aperture;
        case Key::FocalDistance: return o.v[0] == focal_distance_of(c);
    }
    return false;
}

struct Edit {
    std::size_t begin, end;
    std::string text;
};

std::string applied(std::string_view text, std::vector<Edit> edits) {
    std::sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) { return a.begin < b.begin; });
    std::string out;
    std::size_t at = 0;
    for (const Edit& e : edits) {
        out.append(text.substr(at, e.begin - at));
        out += e.text;
        at = e.end;
    }
    out.append(text.substr(at));
    return out;
}

// The last block edited in place so that the merged camera is `camera`; none when it cannot be.
std::optional<std::string> edited_in_place(std::string_view text, const std::vector<Token>& tokens,
                                           const std::vector<BlockTokens>& blocks, const CameraDesc& camera) {
    CameraDesc before;  // what the earlier blocks give
    for (std::size_t i = 0; i + 1 < blocks.size(); ++i) {
        std::vector<Occurrence> block;
        if (!read_block(tokens, blocks[i], block)) return std::nullopt;
        apply_block(block, before);
    }
    const BlockTokens& last = blocks.back();
    std::vector<Occurrence> block;
    if (!read_block(tokens, last, block)) return std::nullopt;
    auto last_of = [&](std::initializer_list<Key> keys) -> const Occurrence* {
        const Occurrence* found = nullptr;
        for (const Occurrence& o : block)
            for (Key k : keys)
                if (o.key == k) found = &o;
        return found;
    };
    std::vector<Edit> edits;
    std::string added;
    // A keyword the block has: its numbers rewritten if they change; one it lacks: added if the
    // earlier blocks (or the defaults) leave the camera different.
    auto settle = [&](Key key, const Occurrence* o, bool needed) {
        const std::string name(kKeys[int(key)].first);
        if (!o) {
            if (needed) added += " " + name + " " + values_of(key, camera);
            return;
        }
        if (o->key != key) edits.push_back({tokens[o->token].begin, tokens[o->token].end, name});  // look <-> focus
        if (o->key != key || !holds(*o, camera)) {
            const std::size_t n = std::size_t(kKeys[int(key)].second);
            edits.push_back({tokens[o->token + 1].begin, tokens[o->token + n].end, values_of(key, camera)});
        }
    };
    settle(Key::Eye, last_of({Key::Eye}), before.eye != camera.eye);
    const Key view = camera.use_focus ? Key::Focus : Key::Look;
    settle(view, last_of({Key::Look, Key::Focus}),
           before.use_focus != camera.use_focus || (camera.use_focus ? before.focus != camera.focus : before.look != camera.look));
    settle(Key::Up, last_of({Key::Up}), before.up != camera.up);
    settle(Key::Angle, last_of({Key::Angle}), before.angle_deg != camera.angle_deg);
    settle(Key::NearFar, last_of({Key::NearFar}),
           before.near_plane != camera.near_plane || before.far_plane != camera.far_plane);
    settle(Key::Aperture, last_of({Key::Aperture}), before.aperture != camera.aperture);
    const std::size_t insert_at = tokens[last.last - 1].end;  // after the block's last word
    // The distance in focus: it matters only through a lens, and only if what the file gives now differs.
    const Occurrence* fd = last_of({Key::FocalDistance});
    settle(Key::FocalDistance, fd, false);
    if (!fd && camera.aperture > 0.0f) {
        const std::string trial = applied(text, [&] {
            std::vector<Edit> e = edits;
            e.push_back({insert_at, insert_at, added});
            return e;
        }());
        const std::optional<CameraDesc> got = merged_camera(trial);
        if (!got || focal_distance_of(*got) != focal_distance_of(camera)) settle(Key::FocalDistance, nullptr, true);
    }
    if (!added.empty()) edits.push_back({insert_at, insert_at, added});
    return applied(text, edits);
}

}  // namespace

CameraReplacement replace_camera_block(std::string_view text, const CameraDesc& camera) {
    CameraReplacement r;
    const std::vector<Token> tokens = tokenize(text);
    const std::vector<BlockTokens> blocks = camera_blocks(tokens, r.error);
    if (!r.error.empty()) return r;
    r.blocks = int(blocks.size());
    if (blocks.empty()) {
        r.block = camera_block(camera);
        r.text = r.block + "\n" + std::string(text);
        return r;
    }
    const std::size_t begin = tokens[blocks.back().first].begin, end = tokens[blocks.back().last].end;
    std::optional<std::string> edited = edited_in_place(text, tokens, blocks, camera);
    const std::optional<CameraDesc> got = edited ? merged_camera(*edited) : std::nullopt;
    if (got && same_image(*got, camera)) {
        r.text = std::move(*edited);
    } else {
        // Not to be edited (a block that cannot be read): replaced by a complete one, which with
        // earlier blocks still in the file states everything they could set.
        r.text = std::string(text.substr(0, begin)) + camera_block(camera, blocks.size() > 1) + std::string(text.substr(end));
    }
    // The block is where the old one was: the text after it is unchanged.
    const std::size_t new_end = r.text.size() - (text.size() - end);
    r.block = r.text.substr(begin, new_end - begin);
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

constexpr std::size_t kMaxSceneBytes = std::size_t(256) << 20;

}  // namespace

CameraSave plan_camera_save(const std::string& path, const CameraDesc& camera) {
    CameraSave plan;
    plan.path = path;
    const FileContents file = read_regular_file(path, kMaxSceneBytes);
    if (!file.ok()) {
        plan.error = "cannot read '" + path + "': " + file.error;
        return plan;
    }
    plan.old_text = file.bytes;
    // A CSCI 1230 JSON file (§9.5) has no camera block to replace: a bracket block would break it.
    if (cs1230::is_json_scene(path, plan.old_text)) {
        plan.error = "'" + path + "' is a CSCI 1230 JSON file, whose camera the viewer does not write: set its "
                     "cameraData by hand (File > Copy camera gives the eye, focus, up and angle)";
        return plan;
    }
    plan.replacement = replace_camera_block(plan.old_text, camera);
    if (!plan.replacement.error.empty()) plan.error = path + ": " + plan.replacement.error;
    return plan;
}

std::string commit_camera_save(const CameraSave& plan) {
    namespace fs = std::filesystem;
    if (!plan.error.empty()) return plan.error;
    const std::string& path = plan.path;
    {
        const FileContents now = read_regular_file(path, kMaxSceneBytes);
        if (!now.ok() || now.bytes != plan.old_text) return "'" + path + "' changed since: nothing written (save again)";
    }
    const std::string& text = plan.replacement.text;
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
    bool ok = write_all(fd, text) && ::fsync(fd) == 0;
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
    ok = out >= 0 && write_all(out, text) && ::fsync(out) == 0;
    error = errno;
    if (out >= 0) ok = (::close(out) == 0) && ok;
    if (!ok) return "cannot write '" + path + "': " + std::strerror(error) + " (the new text is in '" + tmp + "')";
    ::unlink(tmp.c_str());
    return "";
}

std::string save_camera_into_file(const std::string& path, const CameraDesc& camera) {
    return commit_camera_save(plan_camera_save(path, camera));
}

}  // namespace whitted::viewer
