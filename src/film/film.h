#pragma once
// Where samples land: per pixel of a region of the image, the float sum of the samples' colours
// and their count. Linear values stay (for float image formats and for adding more samples
// later); the 8-bit image is made from them (§7 conversion). A region can be rendered on its own
// (a tile, a viewer pass, another machine's share) and its pixels copied into the whole.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "film/image.h"
#include "film/pixel_region.h"
#include "film/view_transform.h"

namespace whitted {

struct FilmPixel {
    glm::vec3 sum{0.0f};
    float weight = 0.0f;  // the number of samples added
    // The pixel's mean colour (black without samples).
    glm::vec3 value() const { return weight > 0.0f ? sum / weight : glm::vec3(0.0f); }
};

class Film {
public:
    Film() = default;
    // A film for `region` of a width × height image, every pixel without samples.
    Film(int width, int height, const PixelRegion& region);
    // The whole image.
    Film(int width, int height) : Film(width, height, PixelRegion{0, 0, width, height}) {}

    // Makes this the film of `region` of a width × height image, every pixel without samples
    // (keeping the memory it has: a worker's film reused tile after tile).
    void reset(int width, int height, const PixelRegion& region);

    int width() const { return width_; }
    int height() const { return height_; }
    const PixelRegion& region() const { return region_; }

    // Pixel (x, y) in image coordinates; it must lie in the region.
    FilmPixel& at(int x, int y) { return pixels_[index(x, y)]; }
    const FilmPixel& at(int x, int y) const { return pixels_[index(x, y)]; }

    // Adds one sample's colour to pixel (x, y).
    void add(int x, int y, const glm::vec3& color) {
        FilmPixel& p = at(x, y);
        p.sum += color;
        p.weight += 1.0f;
    }

    // Copies the pixels of `r` (inside both films' regions) from `from`: how the parts of an image
    // rendered apart come together (regions never overlap, so nothing is added twice).
    void copy_from(const Film& from, const PixelRegion& r);
    void copy_from(const Film& from) { copy_from(from, from.region()); }

    // The 8-bit image of the whole film (pixels outside the region black): ⌊255·clamp(v) + 0.5⌋,
    // or each mean colour times `scale` through another view transform.
    Image to_image(ViewTransform view = ViewTransform::Linear, float scale = 1.0f) const;
    // The mean colours unclamped (pixels outside the region black).
    LinearImage to_linear() const;
    // Writes the 8-bit values of the pixels of `r` into `image` (of the film's size).
    void write_to(Image& image, const PixelRegion& r, ViewTransform view = ViewTransform::Linear,
                  float scale = 1.0f) const;
    // Writes the mean colours of the pixels of `r`, unclamped, into `image` (of the film's size).
    void write_to(LinearImage& image, const PixelRegion& r) const;

private:
    std::size_t index(int x, int y) const {
        return std::size_t(y - region_.y0) * std::size_t(region_.width()) + std::size_t(x - region_.x0);
    }
    int width_ = 0, height_ = 0;
    PixelRegion region_;
    std::vector<FilmPixel> pixels_;
};

}  // namespace whitted
