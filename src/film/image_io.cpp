#include "film/image_io.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include <fcntl.h>
#include <unistd.h>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "base/file_replace.h"
#include "film/exr_encode.h"
#include "film/png_encode.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;

std::string extension_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

// The temporary file being written, for a signal handler (image_file_being_written). One writer
// at a time holds it; a second concurrent writer (the viewer saving while a test writes, say)
// is simply not registered.
char g_writing_path[4096];
enum WritingState : int { kFree, kFilling, kNamed };
std::atomic<int> g_writing{kFree};
static_assert(std::atomic<int>::is_always_lock_free, "read from signal handlers");

class WritingGuard {
public:
    explicit WritingGuard(const std::string& tmp) {
        int expected = kFree;
        if (tmp.size() >= sizeof g_writing_path || !g_writing.compare_exchange_strong(expected, kFilling)) return;
        owner_ = true;
        std::memcpy(g_writing_path, tmp.c_str(), tmp.size() + 1);
        g_writing.store(kNamed, std::memory_order_release);
    }
    ~WritingGuard() {
        if (owner_) g_writing.store(kFree, std::memory_order_release);
    }
    WritingGuard(const WritingGuard&) = delete;
    WritingGuard& operator=(const WritingGuard&) = delete;

private:
    bool owner_ = false;
};

// Where the encoders' bytes go: the temporary file, every write checked (stb's own file writers
// report success even when the disk is full), flushed to the disk before it is renamed.
struct FileSink {
    std::FILE* file = nullptr;
    bool ok = true;
    int error = 0;

    explicit FileSink(const std::string& path) : file(std::fopen(path.c_str(), "wb")) {
        if (!file) ok = false, error = errno;
    }
    void write(const void* data, std::size_t size) {
        if (ok && std::fwrite(data, 1, size, file) != size) ok = false, error = errno;
    }
    static void callback(void* context, void* data, int size) {
        static_cast<FileSink*>(context)->write(data, std::size_t(size));
    }
    // Flushes, syncs and closes; false (with error set) if any byte did not make it.
    bool close() {
        if (!file) return false;
        if (ok && (std::fflush(file) != 0 || fsync(fileno(file)) != 0)) ok = false, error = errno;
        if (std::fclose(file) != 0 && ok) ok = false, error = errno;
        file = nullptr;
        return ok;
    }
    ~FileSink() {
        if (file) std::fclose(file);
    }
};

// `name` shortened (keeping its extension) to at most `max_bytes` bytes, not cutting a UTF-8
// character in two: a file name may have 255 bytes, and names derived from it must fit too.
std::string fit_name(const std::string& name, std::size_t max_bytes) {
    if (name.size() <= max_bytes) return name;
    std::string ext = fs::path(name).extension().string();
    if (ext.size() >= max_bytes) ext.clear();
    std::size_t keep = max_bytes - ext.size();
    while (keep > 0 && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) --keep;  // a continuation byte
    return name.substr(0, keep) + ext;
}

constexpr std::size_t kMaxFileName = 255;  // bytes in one path component (NAME_MAX on Linux)

// A fresh name in the target's directory (so that the rename is atomic): hidden, a random part
// to keep concurrent writers apart, the extension last for readers that sniff it, never longer
// than a file name may be, whatever the target's length.
std::string temporary_beside(const std::string& path) {
    const fs::path target(path);
    std::random_device rd;
    const std::string suffix = ".tmp" + std::to_string(rd() % 1000000) + extension_of(path);
    const std::string stem = fit_name(target.stem().string(), kMaxFileName - 1 - suffix.size());
    return (target.parent_path() / ("." + stem + suffix)).string();
}

// PFM: "PF", the size, a negative scale for little-endian floats, then the rows bottom to top.
bool encode_pfm(const LinearImage& image, FileSink& sink) {
    static_assert(sizeof(glm::vec3) == 12);
    const std::string header = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    sink.write(header.data(), header.size());
    for (int y = image.height - 1; y >= 0; --y)
        sink.write(&image.rgb[std::size_t(y) * std::size_t(image.width)], std::size_t(image.width) * sizeof(glm::vec3));
    return sink.ok;
}

// Writes the encoded image to a temporary file beside `path` and renames it over `path` once every
// byte is on the disk. encode(sink) returns false if the image could not be encoded.
// Through a symbolic link the file it leads to is replaced (the link stays), keeping its permissions.
template <class Encode>
std::string write_atomically(const std::string& path, Encode&& encode) {
    const ReplaceTarget target = replace_target(path);
    const std::string tmp = temporary_beside(target.path);
    const WritingGuard guard(tmp);
    FileSink sink(tmp);
    if (sink.ok) keep_permissions(fileno(sink.file), target);
    const bool encoded = sink.ok && encode(sink);
    const bool ok = sink.close() && encoded;
    const int error = sink.error;
    std::error_code ec;
    if (!ok) {
        std::filesystem::remove(tmp, ec);
        return "cannot write '" + path + "': " + (error ? std::strerror(error) : "the image could not be encoded");
    }
    std::filesystem::rename(tmp, target.path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        return "cannot write '" + path + "': " + ec.message();
    }
    return "";
}

LinearImage to_linear(const Image& image) {
    LinearImage out{image.width, image.height, std::vector<glm::vec3>(std::size_t(image.width) * std::size_t(image.height)),
                    image.text};
    for (std::size_t i = 0; i < out.rgb.size(); ++i)
        out.rgb[i] = glm::vec3(image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]) / 255.0f;
    return out;
}

bool encode(const Image& image, const std::string& ext, FileSink& sink) {
    const int w = image.width, h = image.height;
    const auto* px = image.rgb.data();
    if (ext == ".png") return encode_png(image, [&](const void* data, std::size_t size) { sink.write(data, size); });
    if (ext == ".bmp") return stbi_write_bmp_to_func(FileSink::callback, &sink, w, h, 3, px) != 0;
    if (ext == ".jpg" || ext == ".jpeg") return stbi_write_jpg_to_func(FileSink::callback, &sink, w, h, 3, px, 95) != 0;
    const std::string header = "P6\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
    sink.write(header.data(), header.size());
    sink.write(px, image.rgb.size());
    return true;
}

}  // namespace

bool is_linear_output(const std::string& path) {
    const std::string ext = extension_of(path);
    return ext == ".exr" || ext == ".pfm";
}

bool is_supported_output(const std::string& path) {
    std::string ext = extension_of(path);
    return ext == ".png" || ext == ".bmp" || ext == ".ppm" || ext == ".jpg" || ext == ".jpeg" || is_linear_output(path);
}

std::string output_problem(int width, int height, const std::string& path) {
    if (!is_supported_output(path))
        return "cannot write '" + path + "': unknown image format (use .png, .bmp, .ppm, .jpg, .jpeg, .exr or .pfm)";
    if (width <= 0 || height <= 0) return "cannot write '" + path + "': the image is empty";
    const std::string ext = extension_of(path);
    const std::string too_large = "cannot write '" + path + "': " + std::to_string(width) + "x" +
                                  std::to_string(height) + " is too large for " + ext;
    // stb's BMP writer puts the file size, 54 + (3w rounded up to 4)·h, in an int.
    const std::uint64_t bmp_row = (std::uint64_t(width) * 3 + 3) / 4 * 4;
    if (ext == ".bmp" && 54 + bmp_row * std::uint64_t(height) > std::uint64_t(INT_MAX))
        return too_large + " (over 2 GB); use .ppm";
    if ((ext == ".jpg" || ext == ".jpeg") && (width > 65535 || height > 65535))
        return "cannot write '" + path + "': JPEG images are at most 65535 pixels wide and high; use .png or .ppm";
    return "";
}

std::string write_image(const Image& image, const std::string& path) {
    if (std::string problem = output_problem(image.width, image.height, path); !problem.empty()) return problem;
    if (image.rgb.size() != std::size_t(image.width) * std::size_t(image.height) * 3)
        return "cannot write '" + path + "': the image's pixels do not match its size";
    if (is_linear_output(path)) return write_linear_image(to_linear(image), path);
    const std::string ext = extension_of(path);
    return write_atomically(path, [&](FileSink& sink) { return encode(image, ext, sink); });
}

std::string write_linear_image(const LinearImage& image, const std::string& path,
                               const std::vector<ImageLayer>& layers) {
    if (std::string problem = output_problem(image.width, image.height, path); !problem.empty()) return problem;
    if (image.rgb.size() != std::size_t(image.width) * std::size_t(image.height))
        return "cannot write '" + path + "': the image's pixels do not match its size";
    for (const ImageLayer& layer : layers)
        if (layer.values.size() != image.rgb.size() * layer.channels.size())
            return "cannot write '" + path + "': a layer's pixels do not match the image's size";
    if (!layers.empty() && extension_of(path) != ".exr")
        return "cannot write '" + path + "': only OpenEXR (.exr) files hold layers";
    if (!is_linear_output(path)) {
        Image bytes(image.width, image.height);
        bytes.text = image.text;
        for (std::size_t i = 0; i < image.rgb.size(); ++i)
            for (int c = 0; c < 3; ++c) bytes.rgb[3 * i + std::size_t(c)] = to_byte(image.rgb[i][c]);
        return write_image(bytes, path);
    }
    const bool exr = extension_of(path) == ".exr";
    return write_atomically(path, [&](FileSink& sink) {
        if (!exr) return encode_pfm(image, sink);
        // A full disk says "No space left on device", not "the image could not be encoded".
        int error = 0;
        if (!encode_exr(image, sink.file, error, layers)) {
            sink.ok = false;
            sink.error = error;
        } else if (std::fflush(sink.file) != 0) {
            sink.ok = false;
            sink.error = errno;
        }
        return sink.ok;
    });
}

std::string partial_image_path(const std::string& path) {
    const fs::path target(path);
    const std::string ext = target.extension().string();
    const std::string stem = fit_name(target.stem().string(), kMaxFileName - (".partial" + ext).size());
    return (target.parent_path() / (stem + ".partial" + ext)).string();
}

std::string output_unwritable(const std::string& path) {
    const std::string head = "cannot write '" + path + "': ";
    std::error_code ec;
    if (fs::is_directory(path, ec)) return head + "it is a directory";
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::is_directory(parent, ec))
        return head + "the folder '" + parent.string() + "' does not exist";
    // What write_image will do first: create a file beside the target (where a link leads).
    const std::string probe = temporary_beside(replace_target(path).path);
    const int fd = open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) return head + std::strerror(errno);
    close(fd);
    unlink(probe.c_str());
    return "";
}

const char* image_file_being_written() {
    return g_writing.load(std::memory_order_acquire) == kNamed ? g_writing_path : nullptr;
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
