#pragma once
// A rectangle of an image's pixels: a tile, a viewer pass's area, an MPI rank's share.

namespace whitted {

struct PixelRegion {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels [x0, x1) × [y0, y1)
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    bool operator==(const PixelRegion&) const = default;
};

}  // namespace whitted
