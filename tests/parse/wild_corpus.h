#pragma once
// Where the wild scene corpus lives (shared/scenes/wild): $WHITTED_SHARED_DIR/scenes/wild, else
// <source dir>/../shared/scenes/wild. Empty path when absent (tests then skip, saying why).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace whitted {

inline std::filesystem::path wild_corpus_dir() {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (const char* shared = std::getenv("WHITTED_SHARED_DIR")) {
        const fs::path p = fs::path(shared) / "scenes" / "wild";
        if (fs::is_directory(p, ec)) return p;
    }
#ifdef WHITTED_SOURCE_DIR
    const fs::path p = fs::path(WHITTED_SOURCE_DIR) / ".." / "shared" / "scenes" / "wild";
    if (fs::is_directory(p, ec)) return fs::canonical(p, ec);
#endif
    return {};
}

inline std::string wild_corpus_missing_reason() {
    return "wild scene corpus not found: set WHITTED_SHARED_DIR (expects "
           "$WHITTED_SHARED_DIR/scenes/wild) or place it at <source>/../shared/scenes/wild";
}

// All *.sc files under `dir`, sorted, as paths.
inline std::vector<std::filesystem::path> wild_scene_files(const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (auto it = std::filesystem::recursive_directory_iterator(dir, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
        if (it->is_regular_file() && it->path().extension() == ".sc") files.push_back(it->path());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace whitted
