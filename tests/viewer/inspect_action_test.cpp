// The viewer's pixel inspector without a display: the report of a pixel of the shown image,
// the locations its lines name, and the editor command lines.
#include <chrono>
#include <filesystem>

#include <gtest/gtest.h>

#include "inspect/inspect_scene.h"
#include "inspect_action.h"
#include "support/run_process.h"

namespace whitted::viewer {
namespace {

using namespace std::chrono_literals;

TEST(InspectAction, EditorCommandPutsTheLineWhereTheEditorWantsIt) {
    const SourceLoc loc{"/work/s.sc", 12, 5};
    EXPECT_EQ(editor_command("vim", loc), (std::vector<std::string>{"vim", "+12", "/work/s.sc"}));
    EXPECT_EQ(editor_command("emacsclient -n", loc),
              (std::vector<std::string>{"emacsclient", "-n", "+12", "/work/s.sc"}));
    EXPECT_EQ(editor_command("/usr/bin/nano", loc), (std::vector<std::string>{"/usr/bin/nano", "+12", "/work/s.sc"}));
    EXPECT_EQ(editor_command("code --wait", loc),
              (std::vector<std::string>{"code", "--wait", "-g", "/work/s.sc:12:5"}));
    EXPECT_TRUE(editor_command("", loc).empty());
    EXPECT_TRUE(editor_command("   ", loc).empty());
    EXPECT_TRUE(editor_command("vim", SourceLoc{}).empty());  // nothing to open
}

TEST(InspectAction, VisualBeforeEditor) {
    EXPECT_EQ(chosen_editor("gvim", "vi"), "gvim");
    EXPECT_EQ(chosen_editor("", "vi"), "vi");
    EXPECT_EQ(chosen_editor(nullptr, "vi"), "vi");
    EXPECT_EQ(chosen_editor(nullptr, nullptr), "");
}

TEST(InspectAction, FindsTheLocationOnAReportLine) {
    auto loc = location_in_line("object: sphere at scene.sc:12:5", "/d");
    ASSERT_TRUE(loc);
    EXPECT_EQ(loc->file, "/d/scene.sc");
    EXPECT_EQ(loc->line, 12);
    EXPECT_EQ(loc->col, 5);
    loc = location_in_line("  in subgraph pillar at sub/parts.sc:3:14", "/d");
    ASSERT_TRUE(loc);
    EXPECT_EQ(loc->file, "/d/sub/parts.sc");
    EXPECT_EQ(loc->line, 3);
    loc = location_in_line("light 1 (point at /abs/l.sc:7:1): lit, n.l 0.5000", "/d");
    ASSERT_TRUE(loc);
    EXPECT_EQ(loc->file, "/abs/l.sc");
    EXPECT_EQ(loc->line, 7);  // the "):" after it is punctuation
    EXPECT_EQ(loc->col, 1);
    EXPECT_FALSE(location_in_line("colour 0.1000 0.2000 0.3000 = bytes 26 51 77", "/d"));
    EXPECT_FALSE(location_in_line("camera ray: from (0.0000 0.0000 10.0000)", "/d"));
    EXPECT_FALSE(location_in_line("", "/d"));
}

TEST(InspectAction, ReportsAPixelOfTheShownImage) {
    RenderController c;
    EXPECT_FALSE(inspect_shown_pixel(c, 0, 0).ok);  // nothing shown yet
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "scene.sc", test::kInspectScene);
    RenderJob settings;
    settings.width = test::kInspectWidth;
    settings.height = test::kInspectHeight;
    c.start(scene, LoadOptions{}, settings);
    ASSERT_TRUE(c.wait(60s));
    ASSERT_EQ(c.status().state, RenderState::Finished) << c.status().message;

    const glm::ivec2 px = test::project(test::kLeftPillarFront);
    const InspectResult r = inspect_shown_pixel(c, px.x, px.y);
    ASSERT_TRUE(r.ok) << r.message;
    const test::TextPos obj = test::find_in_scene("object cylinder");
    const std::string where = "scene.sc:" + std::to_string(obj.line) + ":" + std::to_string(obj.col);
    EXPECT_NE(r.text.find("object: cylinder at " + where + "\n"), std::string::npos) << r.text;
    EXPECT_EQ(r.report.bytes, c.image().at(px.x, px.y));  // the pixel on screen
    // The object line, clicked, opens the scene file itself at that line.
    const auto line_start = r.text.find("object: ");
    const auto loc = location_in_line(r.text.substr(line_start, r.text.find('\n', line_start) - line_start), r.base_dir);
    ASSERT_TRUE(loc);
    EXPECT_TRUE(std::filesystem::equivalent(loc->file, scene));
    EXPECT_EQ(loc->line, obj.line);

    const InspectResult outside = inspect_shown_pixel(c, test::kInspectWidth, 0);
    EXPECT_FALSE(outside.ok);
    EXPECT_NE(outside.message.find("outside"), std::string::npos);
}

}  // namespace
}  // namespace whitted::viewer
