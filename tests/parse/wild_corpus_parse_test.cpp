// Every real scene file of the wild corpus (shared/scenes/wild, see SOURCES.md there) parses or
// fails exactly as expected. The expectations are written down here file by file, with the
// reason, so that any change in behaviour shows up as a named regression.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "parse/parser.h"
#include "support/wild_corpus.h"
#include "support/needs.h"

namespace whitted {
namespace {

void check_corpus(bool lenient) {
    const auto dir = wild_corpus_dir();
    WHITTED_NEEDS(test::kSkipSharedTests, dir.empty() ? wild_corpus_missing_reason() : "");
    const auto failures = lenient ? lenient_failures() : strict_failures();
    const auto files = wild_scene_files(dir);
    ASSERT_FALSE(files.empty()) << "no .sc files under " << dir;

    ParseOptions options;
    options.lenient = lenient;
    std::map<std::string, bool> seen;
    for (const auto& file : files) {
        const std::string name = corpus_name(file, dir);
        const ParseResult r = parse_scene_file(file.string(), options);
        const auto expected = failures.find(name);
        if (expected == failures.end()) {
            EXPECT_TRUE(r.ok()) << name << " should load; first diagnostic: "
                                << (r.diagnostics.empty() ? "" : r.diagnostics.back().str());
            if (r.ok()) {
                EXPECT_GE(r.scene.root, 0) << name;
            }
            continue;
        }
        seen[name] = true;
        const Expected& e = expected->second;
        ASSERT_FALSE(r.ok()) << name << " should fail (" << e.why << ")";
        const Diagnostic* first = nullptr;  // the diagnostics are in position order
        for (const auto& diag : r.diagnostics)
            if (!first && diag.severity == Severity::Error) first = &diag;
        ASSERT_NE(first, nullptr) << name;
        const Diagnostic& d = *first;
        EXPECT_EQ(d.severity, Severity::Error) << name;
        EXPECT_EQ(d.loc.file, file.string()) << name;
        EXPECT_EQ(d.loc.line, e.line) << name << ": " << d.str();
        EXPECT_EQ(d.loc.col, e.col) << name << ": " << d.str();
        EXPECT_NE(d.message.find(e.message), std::string::npos)
            << name << ": expected \"" << e.message << "\" in: " << d.str();
        if (std::string(e.message) == "empty scene file") {  // really empty, not misread
            EXPECT_EQ(std::filesystem::file_size(file), 0u) << name;
        }
    }
    for (const auto& [name, e] : failures)
        EXPECT_TRUE(seen.count(name)) << "expected-invalid file missing from the corpus: " << name;
}

TEST(ParseWildCorpus, StrictMode) { check_corpus(false); }

TEST(ParseWildCorpus, LenientModeLoadsTheExtensions) { check_corpus(true); }

TEST(ParseWildCorpus, StrictModeWarnsForWhatItSkips) {
    // §9.4: these load in strict mode, with one warning for each thing that is not drawn.
    const auto dir = wild_corpus_dir();
    WHITTED_NEEDS(test::kSkipSharedTests, dir.empty() ? wild_corpus_missing_reason() : "");
    const std::pair<std::string, const char*> cases[] = {
        {kIndex + "idx58331149_castle.sc", "'alpha'"},
        {kCitelao + "mcgurther_mark_chairs.sc", "'cow'"},
        {kSuziray + "cse452shell/war_and_peace.sc", "'cactus'"},
        {kTufts + "all_effects.sc", "'mesh'"},
    };
    for (const auto& [name, word] : cases) {
        const ParseResult r = parse_scene_file((dir / name).string());
        ASSERT_TRUE(r.ok()) << name;
        bool warned = false;
        for (const auto& d : r.diagnostics)
            warned = warned || (d.severity == Severity::Warning && d.loc.line > 0 &&
                                d.message.find(word) != std::string::npos);
        EXPECT_TRUE(warned) << name << " should warn about " << word;
    }
}

TEST(ParseWildCorpus, DialectIsDetectedPerFile) {
    const auto dir = wild_corpus_dir();
    WHITTED_NEEDS(test::kSkipSharedTests, dir.empty() ? wild_corpus_missing_reason() : "");
    int brown = 0;
    for (const auto& file : wild_scene_files(dir)) {
        const ParseResult r = parse_scene_file(file.string());
        if (!r.ok()) continue;
        const bool tufts = corpus_name(file, dir).rfind(kTufts, 0) == 0;
        EXPECT_EQ(r.scene.dialect, tufts ? Dialect::BrownTufts : Dialect::Labs) << corpus_name(file, dir);
        brown += r.scene.dialect == Dialect::BrownTufts;
    }
    EXPECT_EQ(brown, 5);  // all.sc, all_effects.sc, all_objects.sc, mirror_test.sc, shadow_test.sc
}

TEST(ParseWildCorpus, MissingOpeningBracketsAreFine) {
    // `object cylinder diffuse 1 1 1 ]` without '[': '[' is optional, so the brackets balance.
    const auto dir = wild_corpus_dir();
    WHITTED_NEEDS(test::kSkipSharedTests, dir.empty() ? wild_corpus_missing_reason() : "");
    const ParseResult r =
        parse_scene_file((dir / kIndex / "idx22671205228_disk_missing_brackets.sc").string());
    ASSERT_TRUE(r.ok());
    const SubgraphDesc& disk = r.scene.subgraphs.at(r.scene.find_subgraph("disk"));
    ASSERT_EQ(disk.children.size(), 2u);
    EXPECT_EQ(disk.children[0].objects.at(0).kind, ShapeKind::Cylinder);
    EXPECT_EQ(r.scene.lights.size(), 3u);
}

TEST(ParseWildCorpus, TrailingCommasAreWarnings) {
    const auto dir = wild_corpus_dir();
    WHITTED_NEEDS(test::kSkipSharedTests, dir.empty() ? wild_corpus_missing_reason() : "");
    const ParseResult r = parse_scene_file((dir / kCitelao / "foostable.sc").string());
    ASSERT_TRUE(r.ok());
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics[0].loc.line, 463);  // `ambient 0.2125, 0.1275, 0.054`
    EXPECT_NE(r.diagnostics[0].message.find("','"), std::string::npos);
}

}  // namespace
}  // namespace whitted
