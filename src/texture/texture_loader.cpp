#include "texture/texture_loader.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <unordered_map>

#include <stb/stb_image.h>

#include "texture/ascii_ppm.h"

namespace whitted {
namespace fs = std::filesystem;
namespace {

// stb_image reads zeros past the end of a truncated BMP, TGA or PPM and reports success; such a
// file decodes differently once bytes are appended. PNG's own checks already catch truncation.
bool decoded_past_the_end(const std::vector<unsigned char>& bytes, const unsigned char* data, int w, int h) {
    static const unsigned char kPng[] = {0x89, 'P', 'N', 'G'};
    if (bytes.size() >= 4 && std::equal(kPng, kPng + 4, bytes.begin())) return false;
    std::vector<unsigned char> padded(bytes);
    padded.resize(bytes.size() + 4096, 0xFF);  // more than any one pixel's bytes
    int pw = 0, ph = 0, pn = 0;
    unsigned char* again = stbi_load_from_memory(padded.data(), int(padded.size()), &pw, &ph, &pn, 3);
    const bool same = again && pw == w && ph == h && std::equal(data, data + std::size_t(w) * h * 3, again);
    stbi_image_free(again);
    return !same;
}

bool read_file(const std::string& path, std::vector<unsigned char>& bytes, std::string& reason) {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) {
        reason = "cannot read '" + path + "'";
        return false;
    }
    return true;
}

// Decodes the bytes of file `path` to linear floats (texel = byte / 255, no gamma decoding;
// alpha ignored).
bool decode(const std::vector<unsigned char>& bytes, const std::string& path, TextureImage& out, std::string& reason) {
    if (bytes.size() > std::size_t(std::numeric_limits<int>::max())) {
        reason = "cannot decode '" + path + "': the file is too large";
        return false;
    }
    if (is_ascii_ppm(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()))) {
        std::string why;
        if (decode_ascii_ppm(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), out, why))
            return true;
        reason = "cannot decode '" + path + "': " + why;
        return false;
    }
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load_from_memory(bytes.data(), int(bytes.size()), &w, &h, &n, 3);
    if (!data) {
        reason = std::string("cannot decode '") + path + "': " + (stbi_failure_reason() ? stbi_failure_reason() : "?");
        return false;
    }
    if (decoded_past_the_end(bytes, data, w, h)) {
        stbi_image_free(data);
        reason = "cannot decode '" + path + "': the file ends before its last pixel (truncated)";
        return false;
    }
    out.width = w;
    out.height = h;
    out.texels.resize(std::size_t(w) * h);
    for (std::size_t i = 0; i < out.texels.size(); ++i)
        out.texels[i] = glm::vec3(data[3 * i], data[3 * i + 1], data[3 * i + 2]) / 255.0f;
    stbi_image_free(data);
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
    img.texels.reserve(std::size_t(kSize) * kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            img.texels.push_back(((x / kTexelsPerSquare + y / kTexelsPerSquare) & 1) ? glm::vec3(0.0f)
                                                                                     : glm::vec3(1, 0, 1));
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

bool is_windows_path(const std::string& name) {
    const bool drive = name.size() >= 2 && name[1] == ':' &&
                       ((name[0] >= 'A' && name[0] <= 'Z') || (name[0] >= 'a' && name[0] <= 'z'));
    return drive || name.find('\\') != std::string::npos;
}

std::vector<std::string> loose_texture_candidates(const std::string& name, const std::string& scene_path,
                                                  const std::vector<std::string>& search_dirs) {
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
            if (other != p && fs::is_regular_file(other, ec)) add(other.string());
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

    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const ObjectDesc* src = flat.material_sources[m];
        if (!src || !src->material.texture) continue;
        const TextureRef& ref = *src->material.texture;
        if (auto it = index_of_name.find(ref.file); it != index_of_name.end()) {
            scene.materials[m].texture = it->second;  // -1: already reported missing
            continue;
        }
        if (options.preread) {
            // Another process did the search: decode what it found, or call the name missing.
            int index = -1;
            if (auto f = options.preread->find(ref.file); f != options.preread->end()) {
                TextureImage img;
                std::string why;
                if (decode(f->second, ref.file, img, why)) {
                    index = int(scene.textures.size());
                    scene.textures.push_back(std::move(img));
                }
            }
            if (index < 0) {
                const bool as_checker = options.missing == MissingTexturePolicy::Checker;
                missing.push_back({ref.file, ref.loc, {}, "not among the files received"});
                diagnostics.push_back({as_checker ? Severity::Warning : Severity::Error, ref.loc,
                                       "texture '" + ref.file + "': not among the files received"});
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
        std::vector<std::string> candidates;
        if (auto o = options.overrides.find(ref.file); o != options.overrides.end()) candidates.push_back(o->second);
        for (auto& c : texture_candidates(ref.file, scene_path, options.search_dirs)) candidates.push_back(c);
        if (ref.loose_lookup || is_windows_path(ref.file))
            for (auto& c : loose_texture_candidates(ref.file, scene_path, options.search_dirs)) candidates.push_back(c);

        int index = -1;
        std::string reason;  // the first decoder complaint, if a file was found but unreadable
        std::vector<std::string> tried;
        for (const std::string& c : candidates) {
            tried.push_back(c);
            std::error_code ec;
            if (!fs::is_regular_file(c, ec)) continue;
            std::string key = fs::weakly_canonical(c, ec).string();
            if (ec) key = fs::absolute(c).lexically_normal().string();
            if (auto f = index_of_file.find(key); f != index_of_file.end()) {
                index = f->second;
                if (kept && options.keep_files) (*kept)[ref.file] = (*kept)[name_of_file[key]];  // another spelling
                break;
            }
            TextureImage img;
            std::string why;
            std::vector<unsigned char> bytes;
            if (!read_file(c, bytes, why) || !decode(bytes, c, img, why)) {
                // Found but unreadable: remember why and keep looking; a later place may hold a good copy.
                if (reason.empty()) reason = why;
                continue;
            }
            index = int(scene.textures.size());
            scene.textures.push_back(std::move(img));
            index_of_file[key] = index;
            name_of_file[key] = ref.file;
            if (kept && options.keep_files) (*kept)[ref.file] = std::move(bytes);
            if (files_read) files_read->push_back(c);
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
