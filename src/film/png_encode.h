#pragma once
// 8-bit RGB PNG encoding with zlib, fast enough that an interrupted 33-megapixel render is on disk
// in a fraction of a second: every row Sub-filtered, deflate level 1, bands of rows compressed on
// several threads and joined into one zlib stream (each band a flushed deflate stream of its own,
// as pigz does; the Adler-32 sums combined). The file is the same for any thread count.
#include <cstddef>
#include <functional>

#include "film/image.h"

namespace whitted {

// Sends the PNG's bytes, in order, to `write`. False if zlib failed (out of memory).
bool encode_png(const Image& image, const std::function<void(const void*, std::size_t)>& write, int threads = 0);

}  // namespace whitted
