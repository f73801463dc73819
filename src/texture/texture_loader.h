#pragma once
// Finds and decodes the textures a flattened scene's materials name (scene-format.md §8),
// one decode per file however many objects use it.
#include <atomic>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "base/read_file.h"
#include "flatten/flatten.h"
#include "texture/texture_decode.h"

namespace whitted {

enum class MissingTexturePolicy {
    Error,    // a texture that cannot be found or decoded makes the load fail
    Checker,  // draw it as a magenta/black checkerboard, with a warning
};

// The bytes of texture files, by name as written in the scene (`texture NAME`).
using TextureFiles = std::map<std::string, std::vector<unsigned char>>;

struct TextureOptions {
    std::vector<std::string> search_dirs;  // user-given, tried after the built-in places
    // Answers for textures that were missing before: name as written in the scene → file.
    std::map<std::string, std::string> overrides;
    // Names drawn as checkerboards if they are missing, whatever `missing` says (the viewer's
    // user declined to look for them; others are still errors).
    std::set<std::string> checker_names;
    MissingTexturePolicy missing = MissingTexturePolicy::Error;
    // Files another process already found and read (the ranks of an MPI job get rank 0's): when
    // set, each name is decoded from these bytes and no file is looked for; a name not here is missing.
    const TextureFiles* preread = nullptr;
    // Keep the bytes of every file a texture was decoded from (LoadResult::texture_files), to send on.
    bool keep_files = false;
    // For files from others (--untrusted): a texture is read only from inside the scene file's
    // folder or a search dir (links followed only while they stay inside: base/read_file.h);
    // absolute names are refused; outside and missing are one message.
    bool confined = false;
    TextureLimits limits;  // per file, and max_total_bytes for all of a scene's textures together
    const std::atomic<bool>* cancel = nullptr;  // stops reading a file (then every later one is missing)
};

// The folders a confined file (--untrusted) may come from: the scene file's, then each search dir.
std::vector<std::string> confinement_folders(const std::string& scene_path, const std::vector<std::string>& search_dirs);

struct MissingTexture {
    std::string name;                // as written in the scene
    SourceLoc loc;                   // of the `texture` keyword
    std::vector<std::string> tried;  // every path looked at, in order
    std::string reason;              // "not found" or the decoder's complaint
};

// The places FILE is looked for, in order: as written if absolute; relative to the scene
// file's directory; to its parent; to the current directory; then each search dir.
// `\` is read as a directory separator (in FILE and in the search dirs). Every path returned is
// absolute and normalised, without repeats (a scene in the current directory tries it once).
std::vector<std::string> texture_candidates(const std::string& name, const std::string& scene_path,
                                            const std::vector<std::string>& search_dirs);

// True for a name written as a Windows path: a `\` in it, or a drive letter (`C:`).
bool is_windows_path(const std::string& name);

// Where else to look when every texture_candidates place failed, for a name that is a Windows
// path or comes from a Brown/Tufts file (scene-format.md §9.4), in order: the trailing parts of
// the path in the usual places, longest first (`C:\a\image\earth.bmp` → `a/image/earth.bmp`, then
// `image/earth.bmp`, then `earth.bmp`); then, for every place tried so far in its order, the
// files beside it with the same stem and another image extension (`image/earth.ppm`), which
// exist (the others are not listed). Without the places already in `texture_candidates`.
// With `inside` (--untrusted), a file beside is looked for through it: none outside is listed.
std::vector<std::string> loose_texture_candidates(const std::string& name, const std::string& scene_path,
                                                  const std::vector<std::string>& search_dirs,
                                                  const Confinement* inside = nullptr);

// Fills flat.textures and each material's texture index. Each file is decoded once however many
// materials name it. `options.overrides[name]`, when present, is tried before the built-in places.
// A file that is found but cannot be decoded does not end the search: later places are still
// tried (with a warning if one of them works). Returns the textures that could not be had, each
// once, with the first `texture` keyword that named it; under Error each is an error diagnostic,
// under Checker they are drawn as a checkerboard and a warning is added.
// With options.keep_files, `kept` (when given) gets the bytes of each file decoded; `files_read`
// (when given) gets the path of each file decoded (a viewer watches them).
std::vector<MissingTexture> load_textures(FlattenResult& flat, const std::string& scene_path,
                                          const TextureOptions& options, std::vector<Diagnostic>& diagnostics,
                                          TextureFiles* kept = nullptr, std::vector<std::string>* files_read = nullptr);

// A visible stand-in for a missing texture: magenta and black squares.
TextureImage checker_texture();

}  // namespace whitted
