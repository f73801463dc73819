// The perfect hash finds each of the format's words (scene-format.md §2, §6, §9) and nothing else.
#include "parse/keywords.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace whitted {
namespace {

// Written out here from the spec, not taken from the table under test.
const char* const kWords[] = {
    "background", "camera",   "light",     "mastersubgraph", "trans",     "color",   "eye",       "look",
    "focus",      "up",       "angle",     "near-far",       "aperture",  "focaldistance", "type", "position",
    "direction",  "function", "exponent",  "radius",         "number",    "ambient", "translate", "scale",
    "rotate",     "matrixRC", "matrixCR",  "velocity",       "angularrate", "object", "subgraph", "file",
    "diffuse",    "specular", "reflect",   "transparent",    "emit",      "shine",   "ior",       "gloss",
    "texture",    "alpha",    "blend",     "cube",           "cylinder",  "cone",    "sphere",    "ellipsoid",
    "cactus",     "cow",      "mesh",      "point",          "directional", "spotlight",
};

TEST(ParseKeywords, EachWordIsFoundAsItself) {
    std::set<Keyword> seen;
    for (const char* w : kWords) {
        const Keyword k = find_keyword(w);
        EXPECT_NE(k, Keyword::None) << w;
        EXPECT_TRUE(seen.insert(k).second) << w << " shares its keyword";
    }
    EXPECT_EQ(seen.size(), std::size_t(Keyword::Count) - 1);  // and there are no others
    EXPECT_EQ(find_keyword("matrixRC"), Keyword::MatrixRC);
    EXPECT_EQ(find_keyword("matrixCR"), Keyword::MatrixCR);
    EXPECT_EQ(find_keyword("near-far"), Keyword::NearFar);
}

// Every word one byte away from a keyword (changed, dropped or added), in any case, is not one
// unless it is another keyword.
TEST(ParseKeywords, NearMissesAreNotKeywords) {
    const std::set<std::string> words(std::begin(kWords), std::end(kWords));
    int tried = 0;
    for (const std::string w : kWords) {
        std::set<std::string> variants;
        for (std::size_t i = 0; i <= w.size(); ++i) {
            if (i < w.size()) variants.insert(w.substr(0, i) + w.substr(i + 1));
            for (int c = 1; c < 256; ++c) {
                if (i < w.size()) {
                    std::string changed = w;
                    changed[i] = char(c);
                    variants.insert(changed);
                }
                variants.insert(w.substr(0, i) + char(c) + w.substr(i));
            }
        }
        for (const std::string& v : variants) {
            if (words.count(v)) continue;
            EXPECT_EQ(find_keyword(v), Keyword::None) << "'" << v << "'";
            ++tried;
        }
    }
    EXPECT_GT(tried, 50000);
    for (const char* other : {"", "Camera", "CAMERA", "cameras", "matrixrc", "mastersubgraphs", "nan", "1", "[", "]"})
        EXPECT_EQ(find_keyword(other), Keyword::None) << other;
}

}  // namespace
}  // namespace whitted
