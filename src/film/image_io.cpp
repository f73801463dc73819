#include "film/image_io.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

namespace whitted {
namespace {

std::string extension_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

bool write_ppm(const Image& image, const std::string& path) {
    std::ofstream out(path, std::ios::binary);
    out << "P6\n" << image.width << " " << image.height << "\n255\n";
    out.write(reinterpret_cast<const char*>(image.rgb.data()), std::streamsize(image.rgb.size()));
    out.close();
    return bool(out);
}

}  // namespace

bool is_supported_output(const std::string& path) {
    std::string ext = extension_of(path);
    return ext == ".png" || ext == ".bmp" || ext == ".ppm" || ext == ".jpg" || ext == ".jpeg";
}

std::string write_image(const Image& image, const std::string& path) {
    if (!is_supported_output(path))
        return "cannot write '" + path + "': unknown image format (use .png, .bmp, .ppm, .jpg or .jpeg)";
    if (image.width <= 0 || image.height <= 0) return "cannot write '" + path + "': the image is empty";
    const std::string ext = extension_of(path);
    // Same directory as the target, so that the rename is atomic; a random suffix keeps
    // concurrent writers apart. The extension stays last for readers that sniff it.
    std::random_device rd;
    const std::string tmp = path + ".tmp" + std::to_string(rd() % 1000000) + ext;
    const int w = image.width, h = image.height;
    const auto* px = image.rgb.data();
    bool ok = false;
    if (ext == ".png") ok = stbi_write_png(tmp.c_str(), w, h, 3, px, w * 3) != 0;
    else if (ext == ".bmp") ok = stbi_write_bmp(tmp.c_str(), w, h, 3, px) != 0;
    else if (ext == ".ppm") ok = write_ppm(image, tmp);
    else ok = stbi_write_jpg(tmp.c_str(), w, h, 3, px, 95) != 0;
    std::error_code ec;
    if (!ok) {
        std::filesystem::remove(tmp, ec);
        return "cannot write '" + path + "': " + (errno ? std::strerror(errno) : "write failed");
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        return "cannot write '" + path + "': " + ec.message();
    }
    return "";
}

std::string read_image(const std::string& path, Image& out) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 3);
    if (!data) return "cannot read image '" + path + "': " + (stbi_failure_reason() ? stbi_failure_reason() : "unknown error");
    out = Image(w, h);
    std::copy(data, data + std::size_t(w) * h * 3, out.rgb.begin());
    stbi_image_free(data);
    return "";
}

}  // namespace whitted
