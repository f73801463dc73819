// The viewer's "Save camera into scene" on a CSCI 1230 JSON file (scene-format.md §9.5): refused,
// the file left byte for byte (a bracket camera block would break the JSON).
#if __has_include("camera_text.h")  // built only with the viewer (WHITTED_BUILD_VIEWER=ON)
#include "camera_text.h"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "support/run_process.h"

namespace whitted::viewer {
namespace {

TEST(Cs1230ViewerCamera, SavingTheCameraIntoAJsonFileIsRefusedAndTheFileKept) {
    const std::string text = R"({"globalData": {"ambientCoeff": 0.5, "diffuseCoeff": 0.5, "specularCoeff": 0.5},
 "cameraData": {"position": [0, 0, 5], "up": [0, 1, 0], "heightAngle": 45, "focus": [0, 0, 0]}})";
    const std::string path = test::write_file(test::make_temp_dir(), "scene.json", text);
    CameraDesc cam;
    cam.eye = {1, 2, 3};
    const std::string err = save_camera_into_file(path, cam);
    EXPECT_NE(err.find("CSCI 1230 JSON file"), std::string::npos) << err;
    std::ifstream in(path, std::ios::binary);
    std::ostringstream now;
    now << in.rdbuf();
    EXPECT_EQ(now.str(), text);
}

}  // namespace
}  // namespace whitted::viewer
#endif
