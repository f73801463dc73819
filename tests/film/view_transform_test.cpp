// The view transform: the sRGB curve and the filmic fit at hand-computed points, and PNG files
// that say how their bytes are encoded.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "film/film.h"
#include "film/png_encode.h"
#include "film/view_transform.h"

namespace whitted {
namespace {

// IEC 61966-2-1: 12.92·c up to 0.0031308, then 1.055·c^(1/2.4) − 0.055; the two meet there.
TEST(ViewTransform, TheSrgbCurveAtItsKnownPoints) {
    EXPECT_EQ(srgb_encode(0.0f), 0.0f);
    EXPECT_NEAR(srgb_encode(0.0031308f), 0.040450f, 1e-5f);  // the linear segment's end, 12.92 × 0.0031308
    EXPECT_NEAR(srgb_encode(0.5f), 0.735357f, 1e-5f);         // 1.055 × 0.5^(1/2.4) − 0.055
    EXPECT_NEAR(srgb_encode(0.18f), 0.461356f, 1e-5f);        // mid grey
    EXPECT_EQ(srgb_encode(1.0f), 1.0f);
    EXPECT_EQ(srgb_encode(7.0f), 1.0f);
    EXPECT_EQ(srgb_encode(NAN), 0.0f);
    EXPECT_EQ(view_byte(ViewTransform::Srgb, 0.5f), 188);  // ⌊255 × 0.735357 + 0.5⌋
}

TEST(ViewTransform, LinearIsTheLabsClampedConversion) {
    for (float c : {-1.0f, 0.0f, 0.2f, 0.5f, 0.999f, 1.0f, 3.0f, NAN}) EXPECT_EQ(view_byte(ViewTransform::Linear, c), to_byte(c));
}

// Narkowicz's fit x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14), then sRGB; it rolls off instead of
// clipping: values above 1 stay apart.
TEST(ViewTransform, FilmicRollsHighlightsOff) {
    const float grey = 0.18f * (2.51f * 0.18f + 0.03f) / (0.18f * (2.43f * 0.18f + 0.59f) + 0.14f);  // 0.26690
    EXPECT_NEAR(view_encode(ViewTransform::Filmic, 0.18f), srgb_encode(grey), 1e-6f);
    EXPECT_EQ(view_encode(ViewTransform::Filmic, 0.0f), 0.0f);
    float last = -1.0f;
    for (float c = 0.0f; c < 8.0f; c += 0.01f) {
        const float v = view_encode(ViewTransform::Filmic, c);
        EXPECT_GE(v, last) << c;
        last = v;
    }
    EXPECT_LT(view_byte(ViewTransform::Filmic, 1.0f), view_byte(ViewTransform::Filmic, 2.0f));
    EXPECT_LT(view_byte(ViewTransform::Filmic, 2.0f), 255);
}

TEST(ViewTransform, NamesRoundTrip) {
    for (ViewTransform v : {ViewTransform::Linear, ViewTransform::Srgb, ViewTransform::Filmic})
        EXPECT_EQ(parse_view_transform(view_transform_name(v)), v);
    EXPECT_FALSE(parse_view_transform("gamma"));
}

// An exposure scales the film's radiance before the transform: a pixel of 4 (the Cornell box's
// light, say) that clips at exposure 0 comes back below white at −3 stops.
TEST(ViewTransform, ExposureActsOnRadianceBeforeTheTransform) {
    Film film(2, 1);
    film.add(0, 0, glm::vec3(4.0f));
    film.add(1, 0, glm::vec3(2.0f));
    const Image plain = film.to_image();
    EXPECT_EQ(plain.at(0, 0), plain.at(1, 0)) << "both clip to white";
    const Image exposed = film.to_image(ViewTransform::Linear, 0.125f);
    EXPECT_EQ(exposed.at(0, 0).x, 128);  // 4 / 8 = 0.5
    EXPECT_EQ(exposed.at(1, 0).x, 64);   // 2 / 8 = 0.25: ⌊63.75 + 0.5⌋
}

std::string png_of(const Image& image) {
    std::string bytes;
    encode_png(image, [&](const void* p, std::size_t n) { bytes.append(static_cast<const char*>(p), n); }, 1);
    return bytes;
}

// PNG: an sRGB chunk (intent 0) and gAMA 45455 before the data when the bytes are sRGB-encoded;
// neither for linear bytes (shown as they are, as the course's images).
TEST(ViewTransform, PngFilesSayHowTheirBytesAreEncoded) {
    Film film(4, 2);
    film.add(1, 1, glm::vec3(0.5f));
    const std::string srgb = png_of(film.to_image(ViewTransform::Srgb));
    const std::size_t at = srgb.find("sRGB");
    ASSERT_NE(at, std::string::npos);
    EXPECT_EQ(srgb.substr(at - 4, 4), std::string("\0\0\0\1", 4)) << "one byte of data";
    EXPECT_EQ(srgb[at + 4], '\0') << "perceptual intent";
    const std::size_t g = srgb.find("gAMA");
    ASSERT_NE(g, std::string::npos);
    const auto byte = [&](std::size_t i) { return std::uint32_t(static_cast<unsigned char>(srgb[i])); };
    EXPECT_EQ(byte(g + 4) << 24 | byte(g + 5) << 16 | byte(g + 6) << 8 | byte(g + 7), 45455u);
    EXPECT_LT(g, srgb.find("IDAT"));
    const std::string linear = png_of(film.to_image());
    EXPECT_EQ(linear.find("sRGB"), std::string::npos);
    EXPECT_EQ(linear.find("gAMA"), std::string::npos);
}

}  // namespace
}  // namespace whitted
