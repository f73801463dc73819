#pragma once
// How the film's linear values become the 8-bit values of an image file or a window: the view
// transform (Blender's word). The lab's model has no gamma: its images are the linear values,
// clamped (scene-format.md §7), and so are the course's reference images. Path-traced radiance
// shown that way looks dark and crushed to anyone used to pbrt, Mitsuba or Cycles, which encode
// it for an sRGB display; `filmic` also rolls highlights off instead of clipping them.
#include <cstdint>
#include <optional>
#include <string_view>

#include "film/image.h"
#include "film/pixel_region.h"

namespace whitted {

enum class ViewTransform : unsigned char {
    Linear,  // clamp to [0, 1]: the lab's §7 conversion
    Srgb,    // the sRGB transfer function (IEC 61966-2-1) of the clamped value
    Filmic,  // the ACES filmic fit (Narkowicz 2015), then sRGB: highlights roll off smoothly
};

std::optional<ViewTransform> parse_view_transform(std::string_view name);
const char* view_transform_name(ViewTransform view);

// The sRGB encoding of a linear value in [0, 1]: 12.92·c up to 0.0031308, 1.055·c^(1/2.4) − 0.055 above.
float srgb_encode(float c);
// The display value in [0, 1] of a linear value c (NaN: 0).
float view_encode(ViewTransform view, float c);
// ⌊255·view_encode(c) + 0.5⌋.
std::uint8_t view_byte(ViewTransform view, float c);

// The pixels of `r` of `from` times `scale` (an exposure), through `view`, into `to` (both of the
// same size); `to` is marked sRGB-encoded unless the view is linear.
void encode_region(const LinearImage& from, Image& to, const PixelRegion& r, ViewTransform view, float scale = 1.0f);

}  // namespace whitted
