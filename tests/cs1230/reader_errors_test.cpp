// The CSCI 1230 reader's diagnostics: bad JSON, unknown keys, wrong types, missing keys, values out
// of range, each as FILE:LINE:COL at the key or value it is about, every one of a file's errors in
// one run, in file order. Positions are found in the test's own text by a search independent of
// the reader (the line of the n-th occurrence, the column of its first byte).
#include <string>

#include <gtest/gtest.h>

#include "cs1230/json_tree.h"
#include "cs1230/scene_reader.h"

namespace whitted {
namespace {

const std::string kFile = "/course/scenes/bad.json";

// "LINE:COL" of the `nth` occurrence (from 0) of `needle` in `text`.
std::string at(const std::string& text, const std::string& needle, int nth = 0) {
    std::size_t pos = text.find(needle);
    for (int i = 0; i < nth && pos != std::string::npos; ++i) pos = text.find(needle, pos + 1);
    EXPECT_NE(pos, std::string::npos) << needle;
    int line = 1, col = 1;
    for (std::size_t i = 0; i < pos; ++i) {
        if (text[i] == '\n') ++line, col = 1;
        else ++col;
    }
    return std::to_string(line) + ":" + std::to_string(col);
}

std::vector<std::string> errors(const std::string& text, bool warnings = false) {
    std::vector<std::string> out;
    for (const Diagnostic& d : cs1230::read_scene(text, kFile).diagnostics)
        if (warnings || d.severity == Severity::Error) out.push_back(d.str());
    return out;
}

// One error, at `where` (LINE:COL), saying `what`.
void expect_one(const std::string& text, const std::string& where, const std::string& what) {
    const auto e = errors(text);
    ASSERT_EQ(e.size(), 1u) << (e.empty() ? std::string("no error") : e[0] + "\n" + e.back());
    EXPECT_EQ(e[0].rfind(kFile + ":" + where + ": error: ", 0), 0u) << e[0];
    EXPECT_NE(e[0].find(what), std::string::npos) << e[0];
}

const std::string kHead = R"({
  "globalData": {"ambientCoeff": 0.5, "diffuseCoeff": 0.5, "specularCoeff": 0.5},
  "cameraData": {"position": [0, 0, 5], "up": [0, 1, 0], "heightAngle": 45, "look": [0, 0, -1]},
)";

TEST(Cs1230ReaderErrors, BadJsonIsLocatedWhereTheSyntaxBreaks) {
    std::string t = kHead + R"(  "groups": [{"primitives": [{"type": "cube", "diffuse": [1, 1, 1, ]}]}]
})";
    expect_one(t, at(t, "]}]}]"), "not valid JSON");  // the ] after a trailing comma
    t = kHead + R"(  "groups": [{"primitives": [{"type": "cube"
      "diffuse": [1, 1, 1]}]}]
})";
    expect_one(t, at(t, "\"diffuse\""), "not valid JSON");  // a missing comma: at the next key
    t = kHead + R"(  "groups": [{"name": "unfinished)";
    expect_one(t, at(t, "\"unfinished"), "not valid JSON");  // an unterminated string: at its quote
    t = kHead + R"(  "groups": [tru]})";
    expect_one(t, at(t, "tru"), "not valid JSON");
    expect_one("", "1:1", "not valid JSON");
    expect_one("\n  {\"globalData\": ", "2:18", "unexpected end of input");  // just after the last byte
    expect_one("[1, 2]", "1:1", "the scene file must be an object");
    expect_one(std::string(300, '[') + std::string(300, ']'), "1:257", "nested more than 256");
}

TEST(Cs1230ReaderErrors, UnknownKeysAreRefusedAtTheKeyWithASuggestion) {
    std::string t = R"({
  "globalData": {"ambientCoeff": 0.5, "diffuseCoef": 0.5, "diffuseCoeff": 0.5, "specularCoeff": 0.5},
  "cameraData": {"position": [0, 0, 5], "up": [0, 1, 0], "heightAngle": 45, "look": [0, 0, -1]}
})";
    expect_one(t, at(t, "\"diffuseCoef\""), "unknown key 'diffuseCoef' in globalData (did you mean 'diffuseCoeff'?)");
    t = kHead + R"(  "groups": [{"lights": [{"type": "point", "colour": [1, 1, 1], "color": [1, 1, 1],
                           "attenuationCoeff": [1, 0, 0]}]}]
})";
    expect_one(t, at(t, "\"colour\""), "unknown key 'colour' in a light (did you mean 'color'?)");
    t = kHead + R"(  "groups": [{"translation": [1, 0, 0]}]
})";
    expect_one(t, at(t, "\"translation\""), "unknown key 'translation' in a group (did you mean 'translate'?)");
    t = kHead + R"(  "groups": [{"primitives": [{"type": "cube", "emissive": [1, 1, 1]}]}]
})";
    expect_one(t, at(t, "\"emissive\""), "unknown key 'emissive' in a primitive (it may hold: type, meshFile,");
    t = kHead + R"(  "lights": []
})";
    expect_one(t, at(t, "\"lights\""), "unknown key 'lights' in the scene file");
}

TEST(Cs1230ReaderErrors, WrongTypesAndSizesAreRefusedAtTheValue) {
    std::string t = R"({
  "globalData": {"ambientCoeff": 0.5, "diffuseCoeff": "0.5", "specularCoeff": 0.5},
  "cameraData": {"position": [0, 0, 5], "up": [0, 1, 0], "heightAngle": 45, "look": [0, 0, -1]}
})";
    expect_one(t, at(t, "\"0.5\""), "'diffuseCoeff' in globalData must be a number, not a string");
    t = R"({
  "globalData": {"ambientCoeff": 0.5, "diffuseCoeff": 0.5, "specularCoeff": 0.5},
  "cameraData": {"position": [0, 5], "up": [0, 1, 0], "heightAngle": 45, "look": [0, 0, -1]}
})";
    expect_one(t, at(t, "[0, 5]"), "'position' in cameraData must be an array of 3 numbers, not an array of 2 values");
    t = kHead + R"(  "groups": [{"lights": [{"type": "directional", "color": [1, true, 1], "direction": [0, 0, -1]}]}]
})";
    expect_one(t, at(t, "true"), "'color' in a light must hold numbers, not true or false");
    t = kHead + R"(  "groups": [{"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]}]
})";
    expect_one(t, at(t, "[[1"), "'matrix' in a group must be 4 rows of 4 numbers, not 3 rows");
    t = kHead + R"(  "groups": {"primitives": []}
})";
    expect_one(t, at(t, "{\"primitives\""), "'groups' in the scene file must be an array");
    t = kHead + R"(  "groups": [{"primitives": [{"type": "cube", "shininess": 1e39}]}]
})";
    expect_one(t, at(t, "1e39"), "beyond the range of a 32-bit float");
}

TEST(Cs1230ReaderErrors, MissingKeysAreReportedAtTheirObject) {
    std::string t = R"({
  "globalData": {"ambientCoeff": 0.5, "diffuseCoeff": 0.5, "specularCoeff": 0.5},
  "cameraData": {"position": [0, 0, 5], "up": [0, 1, 0], "look": [0, 0, -1]}
})";
    expect_one(t, at(t, "{\"position\""), "cameraData has no 'heightAngle'");
    t = R"({
  "globalData": {"ambientCoeff": 0.5, "diffuseCoeff": 0.5, "specularCoeff": 0.5}
})";
    expect_one(t, "1:1", "the scene file has no 'cameraData'");
    t = kHead + R"(  "groups": [{"lights": [{"type": "spot", "color": [1, 1, 1], "direction": [0, 0, -1],
                                     "attenuationCoeff": [1, 0, 0], "angle": 30}]}]
})";
    expect_one(t, at(t, "{\"type\": \"spot\""), "a light has no 'penumbra'");
    t = kHead + R"(  "groups": [{"primitives": [{"type": "mesh"}]}]
})";
    expect_one(t, at(t, "{\"type\": \"mesh\""), "a primitive has no 'meshFile'");
    t = kHead + R"(  "templateGroups": [{"primitives": []}]
})";
    expect_one(t, at(t, "{\"primitives\""), "a template group has no 'name'");
}

TEST(Cs1230ReaderErrors, ValuesTheCourseCannotDrawAreRefused) {
    std::string t = R"({
  "globalData": {"ambientCoeff": 0.5, "diffuseCoeff": 0.5, "specularCoeff": 0.5},
  "cameraData": {"position": [0, 0, 5], "up": [0, 1, 0], "heightAngle": 45, "look": [0, 0, -1], "focus": [0, 0, 0]}
})";
    expect_one(t, at(t, "\"focus\""), "both 'look' (a direction) and 'focus' (a point)");
    t = R"({
  "globalData": {"ambientCoeff": 0.5, "diffuseCoeff": 0.5, "specularCoeff": 0.5},
  "cameraData": {"position": [0, 0, 5], "up": [0, 0, -2], "heightAngle": 45, "look": [0, 0, -1]}
})";
    expect_one(t, at(t, "[0, 0, -2]"), "'up' in cameraData is parallel to the view direction");
    t = R"({
  "globalData": {"ambientCoeff": 0.5, "diffuseCoeff": 0.5, "specularCoeff": 0.5},
  "cameraData": {"position": [0, 0, 5], "up": [0, 1, 0], "heightAngle": 180, "look": [0, 0, -1]}
})";
    expect_one(t, at(t, "180"), "between 0 and 180");
    t = kHead + R"(  "groups": [{"lights": [{"type": "sun", "color": [1, 1, 1]}]}]
})";
    expect_one(t, at(t, "\"sun\""), "unknown light type 'sun'");
    t = kHead + R"(  "groups": [{"primitives": [{"type": "spere"}]}]
})";
    expect_one(t, at(t, "\"spere\""), "unknown primitive type 'spere' (did you mean 'sphere'?)");
    t = kHead + R"(  "groups": [{"scale": [1, 0, 1], "primitives": [{"type": "cube"}]}]
})";
    expect_one(t, at(t, "{\"scale\""), "this group's transforms are singular");
    t = kHead + R"(  "groups": [{"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]}]
})";
    expect_one(t, at(t, "[[1"), "must be affine");
    t = kHead + R"(  "groups": [{"primitives": [{"type": "cube", "blend": 1.5, "textureFile": "t.png"}]}]
})";
    expect_one(t, at(t, "1.5"), "'blend' must lie between 0 and 1");
    t = kHead + R"(  "templateGroups": [{"name": "tree", "groups": [{"name": "tree"}]}]
})";
    expect_one(t, at(t, "\"tree\"", 1), "a template can use only the templates defined before it");
}

TEST(Cs1230ReaderErrors, EveryErrorOfAFileAtOnceInFileOrder) {
    const std::string t = R"({
  "globalData": {"ambientCoeff": 0.5, "diffuseCoeff": 0.5},
  "cameraData": {"position": [0, 0, 5], "up": [0, 1, 0], "heightAngle": "wide", "look": [0, 0, -1]},
  "groups": [
    {"translate": [1, 2], "primitives": [{"type": "cube", "difuse": [1, 1, 1]}]},
    {"lights": [{"type": "point", "color": [1, 1, 1]}]}
  ]
})";
    const auto e = errors(t);
    const std::vector<std::pair<std::string, std::string>> want = {
        {at(t, "{\"ambientCoeff\""), "globalData has no 'specularCoeff'"},
        {at(t, "\"wide\""), "'heightAngle' in cameraData must be a number"},
        {at(t, "[1, 2]"), "'translate' in a group must be an array of 3 numbers"},
        {at(t, "\"difuse\""), "did you mean 'diffuse'?"},
        {at(t, "{\"type\": \"point\""), "a light has no 'attenuationCoeff'"}};
    ASSERT_EQ(e.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        EXPECT_EQ(e[i].rfind(kFile + ":" + want[i].first + ": error: ", 0), 0u) << e[i];
        EXPECT_NE(e[i].find(want[i].second), std::string::npos) << e[i];
    }
}

TEST(Cs1230ReaderErrors, LenientModeSkipsUnknownKeysWithAWarning) {
    const std::string t = kHead + R"(  "groups": [{"primitives": [{"type": "cube", "emissive": [1, 1, 1]}]}]
})";
    const ParseResult r = cs1230::read_scene(t, kFile, {.lenient = true});
    EXPECT_TRUE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].str().rfind(kFile + ":" + at(t, "\"emissive\"") + ": warning: unknown key 'emissive'", 0), 0u)
        << r.diagnostics[0].str();
    EXPECT_NE(r.diagnostics[0].message.find("skipped (--lenient)"), std::string::npos);
}

TEST(Cs1230ReaderErrors, PastTwentyErrorsTheRestAreCounted) {
    // 30 groups that are numbers: the first 20 listed, then one error at the 21st counting the rest.
    std::string t = kHead + "  \"groups\": [";
    for (int i = 0; i < 30; ++i) t += (i ? ", " : "") + std::to_string(100 + i);
    t += "]\n}";
    const auto e = errors(t);
    ASSERT_EQ(e.size(), 21u);
    EXPECT_EQ(e[0].rfind(kFile + ":" + at(t, "100") + ": error: a group must be an object", 0), 0u) << e[0];
    EXPECT_EQ(e[20], kFile + ":" + at(t, "120") + ": error: 10 more errors not listed (the first of them is here)");
}

TEST(Cs1230ReaderErrors, TemplatesMayNotMultiplyLightsBeyondTheLimit) {
    // Three templates, each using the one before twice, the first with a light: 8 lights.
    const std::string templates = R"(  "templateGroups": [
    {"name": "t0", "lights": [{"type": "directional", "color": [1, 1, 1], "direction": [0, 0, -1]}]},
    {"name": "t1", "groups": [{"name": "t0"}, {"name": "t0"}]},
    {"name": "t2", "groups": [{"name": "t1"}, {"name": "t1"}]},
    {"name": "t3", "groups": [{"name": "t2"}, {"name": "t2"}]}
  ],
  "groups": [{"name": "t3"}]
})";
    cs1230::ReadOptions limits;
    limits.max_lights = 8;
    EXPECT_TRUE(cs1230::read_scene(kHead + templates, kFile, limits).ok());
    EXPECT_EQ(cs1230::read_scene(kHead + templates, kFile, limits).scene.lights.size(), 8u);
    limits.max_lights = 7;
    const ParseResult r = cs1230::read_scene(kHead + templates, kFile, limits);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].str(), kFile + ":1:1: error: the scene has 8 lights once its templates are placed, "
                                              "more than the limit of 7");
}

TEST(Cs1230ReaderErrors, WarningsForWhatTheCourseIgnores) {
    const std::string t = kHead + R"(  "groups": [
    {"primitives": [{"type": "cube", "bumpMapFile": "b.png"}]},
    {"lights": [{"type": "point", "color": [1, 1, 1], "attenuationCoeff": [1, 0, 0], "direction": [0, 0, -1]}]},
    {"translate": [1, 0, 0], "translate": [2, 0, 0]}
  ]
})";
    const auto all = errors(t, true);
    ASSERT_EQ(all.size(), 3u);
    EXPECT_EQ(all[0].rfind(kFile + ":" + at(t, "\"bumpMapFile\"") + ": warning: bump maps are not drawn", 0), 0u) << all[0];
    EXPECT_EQ(all[1].rfind(kFile + ":" + at(t, "\"direction\"") + ": warning: 'direction' has no effect on a point light", 0),
              0u)
        << all[1];
    EXPECT_EQ(all[2].rfind(kFile + ":" + at(t, "\"translate\"", 1) + ": warning: 'translate' is given twice", 0), 0u)
        << all[2];
}

TEST(Cs1230JsonTree, ValuesAndKeysKnowWhereTheyStart) {
    const std::string t = "{\"a\": [1.5, -2e1, \"x\\\"y\"],\n \"b\": {\"c\": null, \"d\": true}}";
    const cs1230::JsonParseResult r = cs1230::parse_json(t);
    ASSERT_TRUE(r.ok) << r.error;
    const cs1230::JsonTree& tree = r.tree;
    const auto& root = tree.node(tree.root);
    ASSERT_EQ(root.count, 2u);
    const auto& a = tree.members[root.first];
    EXPECT_EQ(tree.key(a), "a");
    EXPECT_EQ(a.key_offset, t.find("\"a\""));
    const auto& arr = tree.node(a.value);
    ASSERT_EQ(arr.count, 3u);
    EXPECT_EQ(arr.offset, t.find('['));
    EXPECT_EQ(tree.node(tree.items[arr.first]).offset, t.find("1.5"));
    EXPECT_EQ(tree.node(tree.items[arr.first + 1]).number, -20.0);
    EXPECT_EQ(tree.node(tree.items[arr.first + 1]).offset, t.find("-2e1"));
    EXPECT_EQ(tree.text(tree.node(tree.items[arr.first + 2])), "x\"y");
    const auto& b = tree.members[root.first + 1];
    EXPECT_EQ(b.key_offset, t.find("\"b\""));
    const auto& obj = tree.node(b.value);
    EXPECT_EQ(tree.node(tree.members[obj.first].value).offset, t.find("null"));
    EXPECT_EQ(tree.node(tree.members[obj.first + 1].value).offset, t.find("true"));
    int line = 0, col = 0;
    cs1230::LineIndex(t).locate(std::uint32_t(t.find("\"b\"")), line, col);
    EXPECT_EQ(line, 2);
    EXPECT_EQ(col, 2);
}

}  // namespace
}  // namespace whitted
