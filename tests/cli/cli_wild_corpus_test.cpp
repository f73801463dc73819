// Every scene of the wild corpus through the `whitted` command, as a user would run it: the valid
// ones render a small image (exit 0, textures found with no option), the invalid ones exit 2 with
// `FILE:LINE:COL: error:` and leave no image behind; the same again with --lenient. Exactly 59
// of the 64 render (scene-format.md §9.4).
#include <filesystem>

#include <gtest/gtest.h>

#include "film/image_io.h"
#include "support/run_process.h"
#include "support/wild_corpus.h"
#include "support/needs.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;

void render_corpus(bool lenient) {
    const fs::path dir = wild_corpus_dir();
    WHITTED_NEEDS(test::kSkipSharedTests, dir.empty() ? wild_corpus_missing_reason() : "");
    auto failures = lenient ? lenient_failures() : strict_failures();
    for (const auto& [name, e] : texture_failures()) failures.emplace(name, e);
    const std::string out_dir = test::make_temp_dir();
    int index = 0, rendered = 0;
    for (const fs::path& file : wild_scene_files(dir)) {
        const std::string name = corpus_name(file, dir);
        const std::string out = out_dir + "/" + std::to_string(index++) + ".png";
        std::vector<std::string> argv = {test::cli_path(), file.string(), "-o", out,
                                         "--width", "32", "--height", "24", "-q"};
        if (lenient) argv.push_back("--lenient");
        const test::ProcessResult r = test::run_process(argv);
        const auto expected = failures.find(name);
        if (expected == failures.end()) {
            EXPECT_EQ(r.exit_code, 0) << name << " should render:\n" << r.output;
            Image img;
            EXPECT_EQ(read_image(out, img), "") << name;
            EXPECT_EQ(img.width, 32) << name;
            EXPECT_EQ(img.height, 24) << name;
            ++rendered;
            continue;
        }
        const Expected& e = expected->second;
        EXPECT_EQ(r.exit_code, 2) << name << " should fail (" << e.why << "):\n" << r.output;
        const std::string located = file.string() + ":" + std::to_string(e.line) + ":" +
                                    std::to_string(e.col) + ": error: ";
        EXPECT_NE(r.output.find(located), std::string::npos)
            << name << ": expected \"" << located << "\" in:\n" << r.output;
        EXPECT_NE(r.output.find(e.message), std::string::npos) << name << ":\n" << r.output;
        EXPECT_FALSE(fs::exists(out)) << name << ": a failed run leaves no image";
    }
    // 64 files: 3 empty, the `shear` one, and mirror_test.sc without its texture (§9.4).
    EXPECT_EQ(rendered, 59);
}

TEST(CliWildCorpus, ValidScenesRenderInvalidOnesFailWithALocatedError) { render_corpus(false); }

TEST(CliWildCorpus, LenientModeRendersTheSameFiles) { render_corpus(true); }

TEST(CliWildCorpus, MissingTextureFileRendersWithACheckerboard) {
    const fs::path dir = wild_corpus_dir();
    WHITTED_NEEDS(test::kSkipSharedTests, dir.empty() ? wild_corpus_missing_reason() : "");
    const std::string out = test::make_temp_dir() + "/m.png";
    const test::ProcessResult r =
        test::run_process({test::cli_path(), (dir / kTufts / "mirror_test.sc").string(), "-o", out, "--width", "32",
                           "--height", "24", "-q", "--missing-textures", "checker"});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("drawn as a checkerboard"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(out));
}

}  // namespace
}  // namespace whitted
