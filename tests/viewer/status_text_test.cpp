// The status bar's pixel readout: the bytes shown, and the radiance where it is given.
#include <gtest/gtest.h>

#include "status_text.h"

namespace whitted::viewer {
namespace {

TEST(StatusText, PixelReadoutGivesTheBytesAndTheRadiance) {
    Image image(3, 2);
    image.rgb[(1 * 3 + 2) * 3] = 255;
    EXPECT_EQ(pixel_readout(image, 2, 1), "x 2  y 1   RGB 255 0 0");
    EXPECT_EQ(pixel_readout(image, 2, 1, glm::vec3(4.0f, 0.5125f, 0.0f)),
              "x 2  y 1   RGB 255 0 0   linear 4 0.5125 0");
    EXPECT_EQ(pixel_readout(image, 3, 1), "");
    EXPECT_EQ(pixel_readout(image, -1, 0, glm::vec3(1.0f)), "");
}

}  // namespace
}  // namespace whitted::viewer
