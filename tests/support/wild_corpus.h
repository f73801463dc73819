#pragma once
// Where the wild scene corpus lives (shared/scenes/wild): $WHITTED_SHARED_DIR/scenes/wild, else
// <source dir>/../shared/scenes/wild. Empty path when absent (tests then fail,
// unless WHITTED_SKIP_SHARED_TESTS says why they may skip: support/needs.h).
#include <algorithm>
#include <map>
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

// What each invalid file of the corpus must report, written down file by file with the reason,
// so that any change in behaviour shows up as a named regression. Every other file must load.
struct Expected {
    int line, col;        // of the first error
    const char* message;  // substring of the error message
    const char* why;
};

inline const std::string kCitelao = "citelao__cse452-computer-graphics/data/scenes/";
inline const std::string kSuziray = "suziray__COURSE-452-computer-graphics/cse452/";
inline const std::string kTufts = "spanut01__Graphics/homework/5/data/tests/";
inline const std::string kIndex = "_unattributed__search-index/";

// The files that fail in both modes: the three empty ones and the five of the Tufts dialect, whose
// first error differs between the modes (`tufts`).
inline std::map<std::string, Expected> failures_in_both_modes(const Expected& tufts) {
    const Expected empty{1, 1, "empty scene file", "empty in the original repository"};
    std::map<std::string, Expected> m;
    for (const char* name : {"dukes_adam_park.sc", "freestone_amy.sc", "tucek_jim_snowman.sc"})
        m.emplace(kCitelao + name, empty);
    for (const char* name : {"all.sc", "all_effects.sc", "all_objects.sc", "mirror_test.sc", "shadow_test.sc"})
        m.emplace(kTufts + name, tufts);
    return m;
}

// Files that must FAIL in strict mode (all others must load).
inline std::map<std::string, Expected> strict_failures() {
    auto m = failures_in_both_modes({9, 3, "unknown keyword 'number' in light block",
                                     "older Brown/Tufts dialect (`light [ number 0`, top-level trans)"});
    m.insert({
        {kIndex + "idx58331149_castle.sc",
         {127, 4, "unknown keyword 'alpha' in object block", "student extension `alpha 0.9`"}},
        {kCitelao + "mcgurther_mark_chairs.sc",
         {114, 8, "unknown keyword 'angularrate' in trans block",
          "student extensions `angularrate`, `velocity`, `object cow`"}},
        {kCitelao + "sudarsanam_nisha_undertheshade.sc",
         {110, 1, "unknown keyword 'shear' in trans block", "student extension `shear`"}},
        {kSuziray + "cse452shell/war_and_peace.sc",
         {36, 10, "unknown object type 'ellipsoid'", "student shapes `ellipsoid`, `cactus`"}},
        {kSuziray + "data/scenes/barnett_david.sc",
         {117, 10, "unknown object type 'ellipsoid'", "student edit sphere -> ellipsoid"}},
        {kSuziray + "data/scenes/simple0.sc",
         {20, 12, "unknown object type 'ellipsoid'", "student shape `ellipsoid`"}},
    });
    return m;
}

// Files that must FAIL even in lenient mode (all others must load).
inline std::map<std::string, Expected> lenient_failures() {
    auto m = failures_in_both_modes({20, 1, "'trans' at top level",
                                     "Tufts dialect: scene is top-level trans blocks, no mastersubgraph"});
    m.at(kTufts + "shadow_test.sc") = {56, 1, "'trans' at top level",
                                       "Tufts dialect (8 lights before the first trans)"};
    // Lenient mode skips unknown keywords, not malformed numbers: `diffuse 0.6. 0.6 0.7`.
    m.emplace(kCitelao + "sudarsanam_nisha_undertheshade.sc",
              Expected{138, 9, "expected a number for 'diffuse', found '0.6.'", "malformed number `0.6.`"});
    return m;
}

inline std::string corpus_name(const std::filesystem::path& file, const std::filesystem::path& dir) {
    return file.lexically_relative(dir).generic_string();
}

}  // namespace whitted
