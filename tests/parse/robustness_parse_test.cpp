// The parser never crashes or hangs, whatever the input: random token soup, random bytes,
// truncated and mutated real files. Run the suite under ASan/UBSan (WHITTED_SANITIZE=ON) too.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "parse_test_util.h"
#include "support/wild_corpus.h"
#include "support/needs.h"

namespace whitted {
namespace {

// Every result is well-formed: ok() with only warnings and a root, or errors (every problem
// found, at most 20 listed plus one giving the count of the rest), each with a message and a
// plausible position, all ordered by position.
void expect_sane(const ParseResult& r, std::string_view text, const std::string& what) {
    const int errors = parse_test::count(r, Severity::Error);
    ASSERT_LE(errors, 21) << what;
    if (errors == 0) {
        EXPECT_GE(r.scene.root, 0) << what;
        return;
    }
    const bool count_last = r.diagnostics.back().message.find("not listed") != std::string::npos;
    // A parse error is always somewhere in the text (line 0 would mean "no position"); only the
    // closing count of errors not listed has none of its own.
    const int lines = 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n') +
                                           std::count(text.begin(), text.end(), '\r'));
    for (std::size_t i = 0; i < r.diagnostics.size(); ++i) {
        const Diagnostic& d = r.diagnostics[i];
        EXPECT_FALSE(d.message.empty()) << what;
        if (count_last && i + 1 == r.diagnostics.size()) continue;
        EXPECT_GE(d.loc.line, 1) << what << ": " << d.message;
        EXPECT_LE(d.loc.line, lines) << what << ": " << d.message;
        EXPECT_GE(d.loc.col, 1) << what << ": " << d.message;
    }
    for (std::size_t i = 1; i + (count_last ? 1 : 0) < r.diagnostics.size(); ++i) {
        const SourceLoc &a = r.diagnostics[i - 1].loc, &b = r.diagnostics[i].loc;
        ASSERT_LE(std::pair(a.line, a.col), std::pair(b.line, b.col)) << what;
    }
}

void parse_both_modes(std::string_view text, const std::string& what) {
    expect_sane(parse_test::parse(text, false), text, what + " (strict)");
    expect_sane(parse_test::parse(text, true), text, what + " (lenient)");
}

TEST(ParseRobustness, RandomTokenSoup) {
    const char* vocabulary[] = {
        "[",        "]",          "[",           "]",         "mastersubgraph",
        "root",     "a",          "b",           "trans",     "object",
        "cube",     "sphere",     "ellipsoid",   "subgraph",  "camera",
        "light",    "background", "color",       "eye",       "look",
        "focus",    "up",         "angle",       "near-far",  "type",
        "point",    "spotlight",  "directional", "direction", "function",
        "aperture", "exponent",   "ambient",     "diffuse",   "texture",
        "ior",      "shine",      "translate",   "scale",     "rotate",
        "matrixRC", "matrixCR",   "0",           "1",         "-1",
        ".5",       "1e9",        "1e39",        "nan",       "0,",
        "#",        "#x\n",       "\n",          "\r\n",      "\t",
        "x]",       "[y",         "alpha",
    };
    const size_t n = sizeof vocabulary / sizeof vocabulary[0];
    for (unsigned seed = 0; seed < 3000; ++seed) {
        std::mt19937 rng(seed);
        std::string text;
        const size_t length = rng() % 200;
        for (size_t i = 0; i < length; ++i) {
            text += vocabulary[rng() % n];
            text += ' ';
        }
        parse_both_modes(text, "seed " + std::to_string(seed));
    }
}

TEST(ParseRobustness, RandomBytes) {
    for (unsigned seed = 0; seed < 1000; ++seed) {
        std::mt19937 rng(seed);
        std::string text(rng() % 300, '\0');
        for (char& c : text) c = static_cast<char>(rng() % 256);
        parse_both_modes(text, "bytes seed " + std::to_string(seed));
    }
}

TEST(ParseRobustness, TruncatedAndMutatedWildFiles) {
    const auto dir = wild_corpus_dir();
    WHITTED_NEEDS(test::kSkipSharedTests, dir.empty() ? wild_corpus_missing_reason() : "");
    std::mt19937 rng(12345);
    int files = 0;
    for (const auto& path : wild_scene_files(dir)) {
        std::ifstream in(path, std::ios::binary);
        std::stringstream buffer;
        buffer << in.rdbuf();
        const std::string text = buffer.str();
        const std::string name = path.filename().string();
        // Every truncation point for a stride of bytes, plus a few cut inside the last tokens.
        const size_t stride = std::max<size_t>(1, text.size() / 80);
        for (size_t cut = 0; cut < text.size(); cut += stride)
            parse_both_modes(std::string_view(text).substr(0, cut),
                             name + " cut " + std::to_string(cut));
        // Random byte mutations: deletions, bracket insertions, digit swaps.
        for (int m = 0; m < 25 && !text.empty(); ++m) {
            std::string mutated = text;
            for (int k = 0; k < 3; ++k) {
                const size_t at = rng() % mutated.size();
                // Insertions by concatenation: string::insert trips a GCC 12 -Wrestrict false
                // positive.
                const auto insert = [&](const char* piece) {
                    mutated = mutated.substr(0, at) + piece + mutated.substr(at);
                };
                switch (rng() % 4) {
                    case 0: mutated.erase(at, 1 + rng() % 10); break;
                    case 1: insert(rng() % 2 ? "[" : "]"); break;
                    case 2: mutated[at] = "0.-e,x#["[rng() % 8]; break;
                    default: insert(" 1e40 "); break;
                }
                if (mutated.empty()) break;
            }
            parse_both_modes(mutated, name + " mutation " + std::to_string(m));
        }
        ++files;
    }
    EXPECT_GT(files, 0);
}

}  // namespace
}  // namespace whitted
