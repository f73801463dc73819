#include "texture/jpeg_decode.h"

#include <csetjmp>
#include <cstdio>

#include <jpeglib.h>

namespace whitted {
namespace {

struct ErrorManager {
    jpeg_error_mgr pub;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

extern "C" void on_error(j_common_ptr cinfo) {
    auto* err = reinterpret_cast<ErrorManager*>(cinfo->err);
    (*cinfo->err->format_message)(cinfo, err->message);
    std::longjmp(err->jump, 1);
}

extern "C" void on_message(j_common_ptr) {}  // warnings are counted (num_warnings), not printed

enum class Step { Ok, Failed, TooLarge };

// Only trivially destructible locals here: a longjmp out of libjpeg skips destructors.
Step decode(const unsigned char* data, unsigned long size, const TextureLimits& limits, TextureImage& out,
            ErrorManager& err, unsigned& width, unsigned& height) {
    jpeg_decompress_struct cinfo;
    cinfo.err = jpeg_std_error(&err.pub);
    err.pub.error_exit = on_error;
    err.pub.output_message = on_message;
    err.message[0] = '\0';
    if (setjmp(err.jump)) {
        jpeg_destroy_decompress(&cinfo);
        return Step::Failed;
    }
    jpeg_create_decompress(&cinfo);
    jpeg_mem_src(&cinfo, data, size);
    jpeg_read_header(&cinfo, TRUE);
    width = cinfo.image_width;
    height = cinfo.image_height;
    const unsigned long long texels = 1ull * width * height;
    if (width == 0 || height == 0 || width > unsigned(limits.max_side) || height > unsigned(limits.max_side) ||
        texels > limits.max_texels || texels * 3 > limits.max_total_bytes) {
        jpeg_destroy_decompress(&cinfo);
        return Step::TooLarge;
    }
    cinfo.out_color_space = JCS_RGB;
    jpeg_start_decompress(&cinfo);
    out.width = int(cinfo.output_width);
    out.height = int(cinfo.output_height);
    out.rgb.resize(std::size_t(out.width) * std::size_t(out.height) * 3);  // (out outlives a longjmp)
    while (cinfo.output_scanline < cinfo.output_height) {
        JSAMPROW row = &out.rgb[std::size_t(cinfo.output_scanline) * std::size_t(out.width) * 3];
        jpeg_read_scanlines(&cinfo, &row, 1);
    }
    jpeg_finish_decompress(&cinfo);
    const bool warned = err.pub.num_warnings > 0;
    if (warned) (*err.pub.format_message)(reinterpret_cast<j_common_ptr>(&cinfo), err.message);
    jpeg_destroy_decompress(&cinfo);
    return warned ? Step::Failed : Step::Ok;
}

}  // namespace

std::string decode_jpeg(std::string_view bytes, const TextureLimits& limits, TextureImage& out) {
    ErrorManager err;
    unsigned width = 0, height = 0;
    TextureImage image;
    const Step step = decode(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), limits, image, err,
                             width, height);
    const std::string dims = std::to_string(width) + "x" + std::to_string(height);
    if (step == Step::TooLarge) {
        if (width == 0 || height == 0) return "the image is empty (" + dims + ")";
        if (width > unsigned(limits.max_side) || height > unsigned(limits.max_side))
            return dims + " texels: more than " + std::to_string(limits.max_side) + " across or down";
        if (1ull * width * height > limits.max_texels)
            return dims + " texels: more than the limit of " + std::to_string(limits.max_texels) + " texels";
        return dims + " texels need more than the memory left for textures";
    }
    if (step == Step::Failed) return std::string("corrupt or truncated JPEG (") + err.message + ")";
    out = std::move(image);
    return "";
}

}  // namespace whitted
