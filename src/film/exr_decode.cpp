#include "film/exr_decode.h"

#include <cstdint>
#include <cstring>
#include <exception>
#include <stdexcept>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>

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

}  // namespace

std::string decode_exr(std::string_view bytes, const ImageLimits& limits, LinearImage& out) {
    try {
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
