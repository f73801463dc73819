#pragma once
// Per pixel of a region of the image, a fixed number of floats: what a render's per-term images
// (AOVs) add their samples into, beside the Film that holds the colour. Like Film, a region can be
// rendered on its own and copied into the whole; its owner decides what each float means.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "film/pixel_region.h"

namespace whitted {

class ChannelFilm {
public:
    // Makes this the film of `region` of a width × height image, `channels` floats a pixel, all 0
    // (keeping the memory it has).
    void reset(int width, int height, const PixelRegion& region, int channels) {
        width_ = width;
        height_ = height;
        region_ = region;
        channels_ = channels;
        values_.assign(std::size_t(region.width()) * std::size_t(region.height()) * std::size_t(channels), 0.0f);
    }
    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; }
    const PixelRegion& region() const { return region_; }

    // The floats of pixel (x, y), in image coordinates; it must lie in the region.
    float* at(int x, int y) { return &values_[index(x, y)]; }
    const float* at(int x, int y) const { return &values_[index(x, y)]; }

    // Copies the pixels of `r` (inside both films' regions; the same channel count) from `from`.
    void copy_from(const ChannelFilm& from, const PixelRegion& r) {
        const std::size_t n = std::size_t(r.width()) * std::size_t(channels_);
        for (int y = r.y0; y < r.y1; ++y) std::copy_n(from.at(r.x0, y), n, at(r.x0, y));
    }

private:
    std::size_t index(int x, int y) const {
        return (std::size_t(y - region_.y0) * std::size_t(region_.width()) + std::size_t(x - region_.x0)) *
               std::size_t(channels_);
    }
    int width_ = 0, height_ = 0, channels_ = 0;
    PixelRegion region_;
    std::vector<float> values_;
};

}  // namespace whitted
