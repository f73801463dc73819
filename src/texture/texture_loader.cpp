#include "texture/texture_loader.h"

#include <algorithm>
#include <filesystem>
#include <unordered_map>

#include "parse/read_file.h"
#include "texture/texture_decode.h"

namespace whitted {
namespace fs = std::filesystem;
namespace {

// Reads (a regular file, no bigger than the limit, its size checked before a byte is read) and
// decodes within what is left of the scene's texture memory.
bool decode(const std::string& path, const TextureLimits& limits, TextureImage& out, std::string& reason) {
    FileContents file = read_regular_file(path, limits.max_file_bytes);
    if (!file.ok()) {
        reason = "cannot read '" + path + "': " + file.error;
        return false;
    }
    if (std::string why = decode_texture(file.bytes, limits, out); !why.empty()) {
        reason = "cannot decode '" + path + "': " + why;
        return false;
    }
    return true;
}

// True when `path` (canonical) is `root` (canonical) or inside it.
bool is_inside(const fs::path& path, const fs::path& root) {
    auto [r, p] = std::mismatch(root.begin(), root.end(), path.begin(), path.end());
    return r == root.end() || (std::next(r) == root.end() && r->empty());  // "dir/" ends in an empty part
}

std::string tried_list(const std::vector<std::string>& tried) {
    std::string s;
    for (const auto& t : tried) s += "\n    tried: " + t;
    return s;
}

}  // namespace

TextureImage checker_texture() {
    // 8 × 8 squares of 8 × 8 texels each: bilinear filtering only softens the square edges, so
    // the board stays plainly visible (an 8 × 8-texel image would blur into a smooth gradient).
    constexpr int kSquares = 8, kTexelsPerSquare = 8, kSize = kSquares * kTexelsPerSquare;
    TextureImage img;
    img.width = img.height = kSize;
    img.rgb.reserve(std::size_t(kSize) * kSize * 3);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            img.push_back(((x / kTexelsPerSquare + y / kTexelsPerSquare) & 1) ? glm::u8vec3(0) : glm::u8vec3(255, 0, 255));
    return img;
}

std::vector<std::string> texture_candidates(const std::string& name, const std::string& scene_path,
                                            const std::vector<std::string>& search_dirs) {
    std::string portable = name;
    std::replace(portable.begin(), portable.end(), '\\', '/');
    const fs::path file(portable);
    // Every candidate is made absolute so that a report of the places tried is unambiguous
    // whatever the current directory was; the same place reached twice is tried once.
    auto absolute = [](const fs::path& p) {
        std::error_code ec;
        fs::path a = fs::absolute(p, ec);
        return (ec ? p : a).lexically_normal();
    };
    if (file.is_absolute()) return {file.lexically_normal().string()};
    std::error_code ec;
    const fs::path cwd = fs::current_path(ec);
    const fs::path scene_dir = absolute(fs::path(scene_path)).parent_path();
    std::vector<std::string> out;
    auto add = [&](const fs::path& dir) {
        std::string p = absolute(dir / file).string();
        if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
    };
    add(scene_dir);                // the scene file's directory
    add(scene_dir.parent_path());  // its parent (course layout: `texture scenes/x.bmp` in data/scenes/)
    add(ec ? fs::path(".") : cwd);  // the current directory
    for (const auto& d : search_dirs) {
        std::string dir = d;
        std::replace(dir.begin(), dir.end(), '\\', '/');
        add(fs::path(dir));
    }
    return out;
}

std::vector<MissingTexture> load_textures(FlattenResult& flat, const std::string& scene_path,
                                          const TextureOptions& options, std::vector<Diagnostic>& diagnostics) {
    std::vector<MissingTexture> missing;
    std::unordered_map<std::string, int> index_of_file;  // resolved path → texture index
    std::unordered_map<std::string, int> index_of_name;  // name as written → index (or checker)
    int checker = -1;
    auto& scene = flat.scene;
    TextureLimits left = options.limits;  // max_total_bytes shrinks as textures are loaded
    std::vector<fs::path> roots;  // where a confined texture may be
    if (options.confined) {
        std::error_code ec;
        roots.push_back(fs::weakly_canonical(fs::absolute(fs::path(scene_path), ec).parent_path(), ec));
        for (std::string d : options.search_dirs) {
            std::replace(d.begin(), d.end(), '\\', '/');
            roots.push_back(fs::weakly_canonical(fs::absolute(fs::path(d), ec), ec));
        }
    }
    auto allowed = [&](const std::string& candidate) {
        if (!options.confined) return true;
        std::error_code ec;
        const fs::path real = fs::weakly_canonical(candidate, ec);
        if (ec) return false;
        return std::any_of(roots.begin(), roots.end(), [&](const fs::path& r) { return is_inside(real, r); });
    };

    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const ObjectDesc* src = flat.material_sources[m];
        if (!src || !src->material.texture) continue;
        const TextureRef& ref = *src->material.texture;
        if (auto it = index_of_name.find(ref.file); it != index_of_name.end()) {
            scene.materials[m].texture = it->second;  // -1: already reported missing
            continue;
        }
        std::string portable = ref.file;
        std::replace(portable.begin(), portable.end(), '\\', '/');
        if (options.confined && fs::path(portable).is_absolute()) {
            diagnostics.push_back({Severity::Error, ref.loc,
                                   "texture '" + ref.file + "': an absolute path, refused for a file from others "
                                   "(--untrusted): name it relative to the scene's folder"});
            missing.push_back({ref.file, ref.loc, {}, "an absolute path (--untrusted)"});
            index_of_name[ref.file] = -1;
            continue;
        }
        std::vector<std::string> candidates;
        if (auto o = options.overrides.find(ref.file); o != options.overrides.end()) candidates.push_back(o->second);
        for (auto& c : texture_candidates(ref.file, scene_path, options.search_dirs)) candidates.push_back(c);

        int index = -1;
        std::string reason;  // the first decoder complaint, if a file was found but unreadable
        std::vector<std::string> tried;
        for (const std::string& c : candidates) {
            tried.push_back(c);
            std::error_code ec;
            // Anything there is tried (and a device or a FIFO refused by name); nothing there is "not found".
            if (!fs::exists(c, ec)) continue;
            if (!allowed(c)) {
                if (reason.empty())
                    reason = "'" + c + "' is outside the scene's folder and the --texture-path folders (--untrusted)";
                continue;
            }
            std::string key = fs::weakly_canonical(c, ec).string();
            if (ec) key = fs::absolute(c).lexically_normal().string();
            if (auto f = index_of_file.find(key); f != index_of_file.end()) { index = f->second; break; }
            TextureImage img;
            std::string why;
            if (!decode(c, left, img, why)) {
                // Found but unreadable: remember why and keep looking; a later place may hold a good copy.
                if (reason.empty()) reason = why;
                continue;
            }
            left.max_total_bytes -= img.rgb.size();
            index = int(scene.textures.size());
            scene.textures.push_back(std::move(img));
            index_of_file[key] = index;
            if (!reason.empty())
                diagnostics.push_back({Severity::Warning, ref.loc,
                                       "texture '" + ref.file + "': skipped an unreadable file (" + reason +
                                           "), using '" + c + "'"});
            break;
        }
        if (reason.empty()) reason = "not found";
        if (index < 0) {
            missing.push_back({ref.file, ref.loc, tried, reason});
            const bool as_checker =
                options.missing == MissingTexturePolicy::Checker || options.checker_names.count(ref.file) > 0;
            diagnostics.push_back({as_checker ? Severity::Warning : Severity::Error, ref.loc,
                                   "texture '" + ref.file + "': " + reason +
                                       (as_checker ? " (drawn as a checkerboard)" : "") + tried_list(tried)});
            if (!as_checker) {
                index_of_name[ref.file] = -1;
                continue;
            }
            if (checker < 0) {
                checker = int(scene.textures.size());
                scene.textures.push_back(checker_texture());
            }
            index = checker;
        }
        index_of_name[ref.file] = index;
        scene.materials[m].texture = index;
    }
    return missing;
}

}  // namespace whitted
