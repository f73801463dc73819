#include "film/exr_encode.h"

#include <cerrno>
#include <cstdint>
#include <exception>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

namespace whitted {
namespace {

// OpenEXR's output stream over a C file (it seeks back to fill in the line offsets at the end).
class FileStream : public Imf::OStream {
public:
    FileStream(std::FILE* f, int& error) : Imf::OStream("whitted output"), f_(f), error_(error) {}
    void write(const char c[], int n) override {
        if (std::fwrite(c, 1, std::size_t(n), f_) != std::size_t(n)) fail("write failed");
    }
    std::uint64_t tellp() override { return std::uint64_t(ftello(f_)); }
    void seekp(std::uint64_t pos) override {
        // (Seeking flushes the buffer: a full disk may show here first.)
        if (fseeko(f_, off_t(pos), SEEK_SET) != 0) fail("seek failed");
    }

private:
    // The system's reason is kept before the exception is made (which may change errno).
    [[noreturn]] void fail(const char* what) {
        error_ = errno;
        throw std::runtime_error(what);
    }
    std::FILE* f_;
    int& error_;
};

}  // namespace

bool encode_exr(const LinearImage& image, std::FILE* file, int& error, const std::vector<ImageLayer>& layers) {
    error = 0;
    try {
        FileStream stream(file, error);
        Imf::Header header(image.width, image.height);
        for (const char* c : {"R", "G", "B"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
        for (const ImageLayer& layer : layers)
            for (const std::string& c : layer.channels) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
        for (const auto& [key, value] : image.text) header.insert(key, Imf::StringAttribute(value));
        Imf::OutputFile out(stream, header);
        Imf::FrameBuffer fb;
        char* base = const_cast<char*>(reinterpret_cast<const char*>(image.rgb.data()));
        const std::size_t px = sizeof(glm::vec3), row = px * std::size_t(image.width);
        fb.insert("R", Imf::Slice(Imf::FLOAT, base, px, row));
        fb.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), px, row));
        fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), px, row));
        for (const ImageLayer& layer : layers) {
            char* values = const_cast<char*>(reinterpret_cast<const char*>(layer.values.data()));
            const std::size_t stride = sizeof(float) * layer.channels.size();
            for (std::size_t c = 0; c < layer.channels.size(); ++c)
                fb.insert(layer.channels[c], Imf::Slice(Imf::FLOAT, values + c * sizeof(float), stride,
                                                        stride * std::size_t(image.width)));
        }
        out.setFrameBuffer(fb);
        out.writePixels(image.height);
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace whitted
