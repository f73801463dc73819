#include "film/exr_decode.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>
#include <stdexcept>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfTileDescription.h>

namespace whitted {
namespace {

// OpenEXR's input stream over bytes already in memory (read through base/read_file.h's door):
// every read is checked against the end, so a truncated file is an exception, never a read past it.
class MemoryStream : public Imf::IStream {
public:
    explicit MemoryStream(std::string_view bytes) : Imf::IStream("image"), bytes_(bytes) {}
    bool read(char c[], int n) override {
        if (n < 0 || std::uint64_t(n) > bytes_.size() - pos_) throw std::runtime_error("the file ends early (truncated)");
        std::memcpy(c, bytes_.data() + pos_, std::size_t(n));
        pos_ += std::uint64_t(n);
        return pos_ < bytes_.size();
    }
    std::uint64_t tellg() override { return pos_; }
    void seekg(std::uint64_t pos) override {
        if (pos > bytes_.size()) throw std::runtime_error("a seek past the end of the file");
        pos_ = pos;
    }

private:
    std::string_view bytes_;
    std::uint64_t pos_ = 0;
};

// The header alone, checked before OpenEXR's InputFile sizes its line and tile buffers from it (a
// data window with max < min, or thousands of channels, would have it ask for gigabytes): the
// window within the limits, and the bytes of the largest buffer it may allocate (256 lines of the
// widest, or a tile, at 4 bytes a sample in every channel) no more than the float RGB image of the
// largest size the limits allow.
std::string header_problem(std::string_view bytes, const ImageLimits& limits) {
    if (bytes.size() < 8) return "the file ends early (truncated)";
    int version = 0;
    std::memcpy(&version, bytes.data() + 4, sizeof version);  // little-endian, as the format
    MemoryStream stream(bytes);
    stream.seekg(8);
    Imf::Header header;
    header.readFrom(stream, version);
    const Imath::Box2i window = header.dataWindow();
    const long long w = (long long)window.max.x - window.min.x + 1, h = (long long)window.max.y - window.min.y + 1;
    if (std::string problem = image_size_problem(w, h, limits); !problem.empty()) return problem;
    long long channels = 0;
    for (auto c = header.channels().begin(); c != header.channels().end(); ++c) {
        if (c.channel().xSampling < 1 || c.channel().ySampling < 1) return "a channel with a sampling rate below 1";
        ++channels;
    }
    long long across = w, down = 256;
    if (header.hasTileDescription()) {
        const Imf::TileDescription& t = header.tileDescription();
        across = (long long)t.xSize, down = (long long)t.ySize;
        if (across > limits.max_side || down > limits.max_side) return "a tile larger than an image may be";
    }
    const long long budget = (long long)limits.max_pixels * 12;
    if (channels > 4096 || across * down > budget / 4 / std::max(channels, 1LL))
        return "too many channels (" + std::to_string(channels) + ") for an image of this width";
    return "";
}

}  // namespace

std::string decode_exr(std::string_view bytes, const ImageLimits& limits, LinearImage& out) {
    try {
        if (std::string problem = header_problem(bytes, limits); !problem.empty()) return problem;
        MemoryStream stream(bytes);
        Imf::InputFile file(stream);
        const Imf::Header& header = file.header();
        const Imath::Box2i window = header.dataWindow();
        const long long w = (long long)window.max.x - window.min.x + 1, h = (long long)window.max.y - window.min.y + 1;
        if (std::string problem = image_size_problem(w, h, limits); !problem.empty()) return problem;

        const Imf::ChannelList& channels = header.channels();
        const bool rgb = channels.findChannel("R") || channels.findChannel("G") || channels.findChannel("B");
        const bool grey = !rgb && channels.findChannel("Y");
        if (!rgb && !grey) return "no R, G, B or Y channel (an OpenEXR file of other layers)";
        for (const char* name : {"R", "G", "B", "Y"})
            if (const Imf::Channel* c = channels.findChannel(name); c && (c->xSampling != 1 || c->ySampling != 1))
                return std::string("the ") + name + " channel is subsampled, which is not supported";

        LinearImage image{int(w), int(h), std::vector<glm::vec3>(std::size_t(w) * std::size_t(h), glm::vec3(0.0f)), {}};
        Imf::FrameBuffer fb;
        const std::size_t px = sizeof(glm::vec3), row = px * std::size_t(w);
        char* base = reinterpret_cast<char*>(image.rgb.data());
        if (grey) {
            fb.insert("Y", Imf::Slice::Make(Imf::FLOAT, base, window, px, row));
        } else {
            fb.insert("R", Imf::Slice::Make(Imf::FLOAT, base, window, px, row));
            fb.insert("G", Imf::Slice::Make(Imf::FLOAT, base + sizeof(float), window, px, row));
            fb.insert("B", Imf::Slice::Make(Imf::FLOAT, base + 2 * sizeof(float), window, px, row));
        }
        file.setFrameBuffer(fb);
        file.readPixels(window.min.y, window.max.y);
        if (grey)
            for (glm::vec3& p : image.rgb) p = glm::vec3(p.x);
        out = std::move(image);
        return "";
    } catch (const std::bad_alloc&) {
        throw;  // out of memory is the caller's to report, not a bad file
    } catch (const std::exception& e) {
        return std::string("not a readable OpenEXR image: ") + e.what();
    }
}

}  // namespace whitted
