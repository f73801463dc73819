#pragma once
// Checks a PNG's chunks and the size its pixel data inflates to before stb_image decodes it: stb
// believes a chunk's length (a 282-byte file whose IDAT says 1.8 GB made it reallocate 2 GB) and
// grows its inflate buffer for as long as the data goes on (a zip bomb of a few megabytes inside a
// 64 × 64 image inflates to gigabytes). With these checks stb's buffers stay within a few times the
// file and the pixels' own size.
#include <string>
#include <string_view>

namespace whitted {

// "" if `bytes` (a file that starts with the PNG signature) has every chunk up to IEND inside the
// file and compressed pixel data that inflates to no more than twice what the header's pixels need
// (a little extra after the last row is common and harmless); otherwise why not. Data that zlib
// finds corrupt is left for stb to report.
std::string check_png(std::string_view bytes);

// The bytes of filtered scanlines a PNG of this header needs: a filter byte and the packed
// samples of each row, for each of the seven Adam7 passes when interlaced. 0 for an invalid header.
unsigned long long png_filtered_bytes(unsigned width, unsigned height, int bit_depth, int colour_type, int interlace);

}  // namespace whitted
