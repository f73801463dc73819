#include "texture/texture_loader.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <unordered_map>

#include <unistd.h>

#include "base/read_file.h"
#include "texture/texture_decode.h"

namespace whitted {
namespace fs = std::filesystem;
namespace {

// Decodes within what is left of the scene's texture memory.
bool decode(const std::string& path, const std::string& bytes, const TextureLimits& limits, TextureImage& out,
            std::string& reason) {
    if (std::string why = decode_texture(bytes, limits, out); !why.empty()) {
        reason = "cannot decode '" + path + "': " + why;
        return false;
    }
    return true;
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

std::vector<std::string> confinement_folders(const std::string& scene_path, const std::vector<std::string>& search_dirs) {
    std::error_code ec;
    std::vector<std::string> folders{fs::absolute(fs::path(scene_path), ec).parent_path().string()};
    for (std::string d : search_dirs) {
        std::replace(d.begin(), d.end(), '\\', '/');
        folders.push_back(d);
    }
    return folders;
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

bool is_windows_path(const std::string& name) {
    const bool drive = name.size() >= 2 && name[1] == ':' &&
                       ((name[0] >= 'A' && name[0] <= 'Z') || (name[0] >= 'a' && name[0] <= 'z'));
    return drive || name.find('\\') != std::string::npos;
}

std::vector<std::string> loose_texture_candidates(const std::string& name, const std::string& scene_path,
                                                  const std::vector<std::string>& search_dirs,
                                                  const Confinement* inside) {
    std::string portable = name;
    std::replace(portable.begin(), portable.end(), '\\', '/');
    std::vector<std::string> parts;
    for (const auto& p : fs::path(portable).relative_path()) parts.push_back(p.string());
    const std::vector<std::string> usual = texture_candidates(name, scene_path, search_dirs);
    std::vector<std::string> places = usual;  // every place, to look beside each for other extensions
    std::vector<std::string> out;
    auto add = [&](const std::string& c) {
        if (std::find(places.begin(), places.end(), c) == places.end()) places.push_back(c);
        if (std::find(usual.begin(), usual.end(), c) == usual.end() &&
            std::find(out.begin(), out.end(), c) == out.end())
            out.push_back(c);
    };
    // The trailing parts, longest first; the whole path was the usual look-up.
    for (std::size_t first = 1; first < parts.size(); ++first) {
        fs::path tail;
        for (std::size_t i = first; i < parts.size(); ++i) tail /= parts[i];
        for (const std::string& c : texture_candidates(tail.string(), scene_path, search_dirs)) add(c);
    }
    // The same stem with the extensions of the image files that do exist there.
    static const char* const kExtensions[] = {".bmp", ".jpeg", ".jpg", ".png", ".ppm", ".tga"};
    const std::vector<std::string> tried = places;
    for (const std::string& c : tried) {
        const fs::path p(c);
        for (const char* ext : kExtensions) {
            fs::path other = p;
            other.replace_extension(ext);
            std::error_code ec;
            if (other == p) continue;
            if (inside) {
                const int fd = inside->open_inside(other.string());
                if (fd >= 0) close(fd), add(other.string());
            } else if (fs::is_regular_file(other, ec)) {
                add(other.string());
            }
        }
    }
    return out;
}

std::vector<MissingTexture> load_textures(FlattenResult& flat, const std::string& scene_path,
                                          const TextureOptions& options, std::vector<Diagnostic>& diagnostics,
                                          TextureFiles* kept, std::vector<std::string>* files_read) {
    std::vector<MissingTexture> missing;
    std::unordered_map<std::string, int> index_of_file;  // resolved path → texture index
    std::unordered_map<std::string, int> index_of_name;  // name as written → index (or checker)
    std::unordered_map<std::string, std::string> name_of_file;  // resolved path → the first name that found it
    int checker = -1;
    auto& scene = flat.scene;
    TextureLimits left = options.limits;  // max_total_bytes shrinks as textures are loaded
    std::unique_ptr<Confinement> inside;  // where a confined texture may be
    if (options.confined && !options.preread)
        inside = std::make_unique<Confinement>(confinement_folders(scene_path, options.search_dirs));

    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const ObjectDesc* src = flat.material_sources[m];
        if (!src || !src->material.texture) continue;
        const TextureRef& ref = *src->material.texture;
        left.gif = ref.allow_gif;  // per texture: a CSCI 1230 file's may be GIF (§9.5)
        if (auto it = index_of_name.find(ref.file); it != index_of_name.end()) {
            scene.materials[m].texture = it->second;  // -1: already reported missing
            continue;
        }
        if (options.preread) {
            // Another process did the search: decode what it found, or call the name missing.
            int index = -1;
            std::string why = "not among the files received";
            if (auto f = options.preread->find(ref.file); f != options.preread->end()) {
                TextureImage img;
                const std::string_view bytes(reinterpret_cast<const char*>(f->second.data()), f->second.size());
                if (std::string problem = decode_texture(bytes, left, img); problem.empty()) {
                    left.max_total_bytes -= stored_texture_bytes(img.width, img.height, left);
                    index = int(scene.textures.size());
                    scene.textures.push_back(std::move(img));
                } else {
                    why = "cannot decode '" + ref.file + "': " + problem;
                }
            }
            if (index < 0) {
                const bool as_checker = options.missing == MissingTexturePolicy::Checker;
                missing.push_back({ref.file, ref.loc, {}, why});
                diagnostics.push_back({as_checker ? Severity::Warning : Severity::Error, ref.loc,
                                       "texture '" + ref.file + "': " + why});
                if (as_checker && checker < 0) {
                    checker = int(scene.textures.size());
                    scene.textures.push_back(checker_texture());
                }
                if (as_checker) index = checker;
            }
            index_of_name[ref.file] = index;
            scene.materials[m].texture = index;
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
        if (ref.loose_lookup || is_windows_path(ref.file))
            for (auto& c : loose_texture_candidates(ref.file, scene_path, options.search_dirs, inside.get())) candidates.push_back(c);

        int index = -1;
        std::string reason;  // the first complaint about a file that was found but unreadable
        std::vector<std::string> tried;
        for (const std::string& c : candidates) {
            tried.push_back(c);
            // Opened first, then checked: what is read is what was opened (confined: from inside).
            FileContents file = read_regular_file(c, left.max_file_bytes, options.cancel, inside.get());
            if (file.missing || file.cancelled) continue;
            if (!file.ok()) {
                if (reason.empty()) reason = "cannot read '" + c + "': " + file.error;
                continue;
            }
            const std::string key = std::to_string(file.device) + ":" + std::to_string(file.inode);
            if (auto f = index_of_file.find(key); f != index_of_file.end()) {
                index = f->second;
                if (kept && options.keep_files) (*kept)[ref.file] = (*kept)[name_of_file[key]];  // another spelling
                break;
            }
            TextureImage img;
            std::string why;
            if (!decode(c, file.bytes, left, img, why)) {
                // Found but unreadable: remember why and keep looking; a later place may hold a good copy.
                if (reason.empty()) reason = why;
                continue;
            }
            left.max_total_bytes -= stored_texture_bytes(img.width, img.height, left);
            index = int(scene.textures.size());
            scene.textures.push_back(std::move(img));
            index_of_file[key] = index;
            name_of_file[key] = ref.file;
            if (kept && options.keep_files) (*kept)[ref.file].assign(file.bytes.begin(), file.bytes.end());
            if (files_read) files_read->push_back(c);
            if (!reason.empty())
                diagnostics.push_back({Severity::Warning, ref.loc,
                                       "texture '" + ref.file + "': skipped an unreadable file (" + reason +
                                           "), using '" + c + "'"});
            break;
        }
        if (reason.empty())
            reason = options.confined
                         ? "not found inside the scene's folder and the --texture-path folders (--untrusted)"
                         : "not found";
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
