#include "film/film.h"

#include <algorithm>

namespace whitted {

Film::Film(int width, int height, const PixelRegion& region)
    : width_(width), height_(height), region_(region),
      pixels_(std::size_t(std::max(0, region.width())) * std::size_t(std::max(0, region.height()))) {}

void Film::reset(int width, int height, const PixelRegion& region) {
    width_ = width;
    height_ = height;
    region_ = region;
    pixels_.assign(std::size_t(std::max(0, region.width())) * std::size_t(std::max(0, region.height())), FilmPixel{});
}

void Film::copy_from(const Film& from, const PixelRegion& r) {
    for (int y = r.y0; y < r.y1; ++y)
        std::copy_n(&from.at(r.x0, y), r.width(), &at(r.x0, y));
}

Image Film::to_image(ViewTransform view, float scale) const {
    Image image(width_, height_);
    write_to(image, region_, view, scale);
    image.srgb = view != ViewTransform::Linear;
    return image;
}

LinearImage Film::to_linear() const {
    LinearImage image{width_, height_, std::vector<glm::vec3>(std::size_t(width_) * std::size_t(height_), glm::vec3(0.0f)), {}};
    for (int y = region_.y0; y < region_.y1; ++y)
        for (int x = region_.x0; x < region_.x1; ++x)
            image.rgb[std::size_t(y) * std::size_t(width_) + std::size_t(x)] = at(x, y).value();
    return image;
}

void Film::write_to(Image& image, const PixelRegion& r, ViewTransform view, float scale) const {
    // Row by row through both arrays (a one-sample 1080p render converts two million pixels).
    const std::size_t n = std::size_t(r.x1 - r.x0);
    if (view != ViewTransform::Linear || scale != 1.0f) {
        for (int y = r.y0; y < r.y1; ++y) {
            const FilmPixel* from = &at(r.x0, y);
            std::uint8_t* p = &image.rgb[(std::size_t(y) * std::size_t(image.width) + std::size_t(r.x0)) * 3];
            for (std::size_t i = 0; i < n; ++i, p += 3) {
                const glm::vec3 c = from[i].value() * scale;
                p[0] = view_byte(view, c.x);
                p[1] = view_byte(view, c.y);
                p[2] = view_byte(view, c.z);
            }
        }
        return;
    }
    for (int y = r.y0; y < r.y1; ++y) {
        const FilmPixel* from = &at(r.x0, y);
        std::uint8_t* p = &image.rgb[(std::size_t(y) * std::size_t(image.width) + std::size_t(r.x0)) * 3];
        for (std::size_t i = 0; i < n; ++i, p += 3) {
            const glm::vec3 c = from[i].value();
            p[0] = to_byte(c.x);
            p[1] = to_byte(c.y);
            p[2] = to_byte(c.z);
        }
    }
}

void Film::write_to(LinearImage& image, const PixelRegion& r) const {
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x)
            image.rgb[std::size_t(y) * std::size_t(image.width) + std::size_t(x)] = at(x, y).value();
}

}  // namespace whitted
