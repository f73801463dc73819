#include "compare/compare_image.h"

#include "base/read_file.h"
#include "texture/texture_decode.h"

namespace whitted {
namespace {

// The format's name from the file's first bytes (the decoders refuse what is not one of them).
std::string format_name(std::string_view b) {
    auto starts = [&](std::string_view magic) { return b.substr(0, magic.size()) == magic; };
    if (starts("\x89PNG")) return "PNG";
    if (starts("\xff\xd8")) return "JPEG";
    if (starts("BM")) return "BMP";
    if (starts("\x76\x2f\x31\x01")) return "OpenEXR";
    if (starts("PF") || starts("Pf")) return "PFM";
    if (starts("P3") || starts("P5") || starts("P6")) return "PPM";
    return "TGA";  // the one format without a magic number
}

}  // namespace

std::string read_compare_image(const std::string& path, CompareImage& out, const CompareLimits& limits) {
    const std::string head = "cannot read image '" + path + "': ";
    FileContents file = read_regular_file(path, limits.max_file_bytes);
    if (!file.ok()) return head + file.error;
    const std::string_view bytes = file.bytes;
    CompareImage image;
    if (is_linear_image_data(bytes)) {
        if (std::string why = decode_linear_image(bytes, limits.image, image.pixels); !why.empty()) return head + why;
        image.linear = true;
    } else {
        TextureLimits tl;
        tl.max_file_bytes = limits.max_file_bytes;
        tl.max_side = limits.image.max_side;
        tl.max_texels = limits.image.max_pixels;
        tl.max_total_bytes = limits.image.max_pixels * 3;
        TextureImage bytes_image;
        if (std::string why = decode_texture(bytes, tl, bytes_image); !why.empty()) return head + why;
        image.pixels.width = bytes_image.width;
        image.pixels.height = bytes_image.height;
        image.pixels.rgb.resize(std::size_t(bytes_image.width) * std::size_t(bytes_image.height));
        for (std::size_t i = 0; i < image.pixels.rgb.size(); ++i) image.pixels.rgb[i] = bytes_image.texel(i);
    }
    image.format = format_name(bytes);
    out = std::move(image);
    return "";
}

}  // namespace whitted
