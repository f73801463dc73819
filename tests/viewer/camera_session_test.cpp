// The viewer's camera session, without a display: what the window renders with after each gesture.
#if __has_include("camera_session.h")  // built only with the viewer (WHITTED_BUILD_VIEWER=ON)
#include "camera_session.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "camera_navigation.h"
#include "camera_text.h"
#include "parse/parser.h"
#include "support/run_process.h"

namespace whitted::viewer {
namespace {

CameraDesc file_camera() {
    CameraDesc c;
    c.eye = {0, 1, 6};
    c.focus = {0, 0, 0};
    c.use_focus = true;
    c.angle_deg = 40;
    return c;
}

// The same camera as written: what the renderer and the camera block see.
bool same(const CameraDesc& a, const CameraDesc& b) { return camera_block(a) == camera_block(b); }

TEST(CameraSession, BeforeALoadNoGestureMovesAnything) {
    CameraSession s;
    EXPECT_FALSE(s.current());
    EXPECT_FALSE(s.orbit_drag(10, 0, false));
    EXPECT_FALSE(s.pan_drag(10, 0, 100, true));
    EXPECT_FALSE(s.wheel(1, false));
    EXPECT_FALSE(s.fly('w'));
    EXPECT_FALSE(s.home());
    EXPECT_FALSE(s.moved());
    RenderJob job;
    s.apply(job);
    EXPECT_FALSE(job.camera) << "without a moved camera the job renders the file's";
}

TEST(CameraSession, UnmovedTheJobKeepsTheFilesOwnCamera) {
    CameraSession s;
    s.file_loaded(file_camera());
    ASSERT_TRUE(s.current());
    EXPECT_TRUE(same(*s.current(), file_camera()));
    EXPECT_FALSE(s.moved());
    RenderJob job;
    s.apply(job);
    EXPECT_FALSE(job.camera);  // not a rebuilt one: the file's image byte for byte
}

// Every frame of a drag turns the camera of the press by the whole displacement so far (a horizontal
// orbit adds up: 10 then 20 pixels from the same press is 20, not 30).
TEST(CameraSession, EachFrameOfADragStartsFromTheCameraAtThePress) {
    CameraSession s;
    s.file_loaded(file_camera());
    const CameraDesc start = navigable(file_camera());
    ASSERT_TRUE(s.orbit_drag(10, 0, false));
    ASSERT_TRUE(s.orbit_drag(20, 0, true));
    EXPECT_TRUE(same(*s.current(), orbit(start, 20, 0)));
    EXPECT_FALSE(same(*s.current(), orbit(orbit(start, 10, 0), 20, 0)));
    EXPECT_TRUE(s.moved());
    // The next drag starts where this one ended.
    const CameraDesc ended = *s.current();
    ASSERT_TRUE(s.orbit_drag(5, 0, true));
    EXPECT_TRUE(same(*s.current(), orbit(navigable(ended), 5, 0)));
    RenderJob job;
    s.apply(job);
    EXPECT_TRUE(job.camera);
}

TEST(CameraSession, HomeGoesBackToTheFilesCameraOnce) {
    CameraSession s;
    s.file_loaded(file_camera());
    ASSERT_TRUE(s.fly('w'));
    ASSERT_TRUE(s.wheel(2, true));
    EXPECT_FALSE(same(*s.current(), file_camera()));
    EXPECT_TRUE(s.home());
    EXPECT_TRUE(same(*s.current(), file_camera()));
    EXPECT_FALSE(s.home()) << "already there: nothing to render again";
    s.reset();  // another scene
    EXPECT_FALSE(s.current());
}

TEST(CameraSession, SavingMakesTheMovedCameraTheFilesAndAFailureKeepsIt) {
    const std::string dir = test::make_temp_dir(), scene = dir + "/s.sc";
    std::ofstream(scene) << "camera [ eye 0 1 6 focus 0 0 0 angle 40 ]\nmastersubgraph root [ ]\n";
    CameraSession s;
    s.file_loaded(file_camera());
    ASSERT_TRUE(s.fly('d'));
    const CameraDesc moved = *s.current();
    EXPECT_NE(s.save(s.plan_save(dir + "/missing/s.sc")), "");
    EXPECT_TRUE(s.moved());
    EXPECT_EQ(s.save(s.plan_save(scene)), "");
    EXPECT_FALSE(s.moved());
    std::ifstream in(scene);
    const std::string text{std::istreambuf_iterator<char>(in), {}};
    const ParseResult back = parse_scene_text(text, scene);
    ASSERT_TRUE(back.ok()) << text;
    EXPECT_TRUE(same(back.scene.camera, moved)) << text;
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace whitted::viewer
#endif
