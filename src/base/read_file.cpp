#include "base/read_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace whitted {
namespace {

class Fd {
public:
    explicit Fd(int fd) : fd_(fd) {}
    ~Fd() {
        if (fd_ >= 0) close(fd_);
    }
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    Fd(Fd&& o) noexcept : fd_(o.fd_) { o.fd_ = -1; }
    int get() const { return fd_; }

private:
    int fd_;
};

// Opens `path` for reading if it is a regular file (without blocking on a FIFO); fills
// out.error and returns an invalid Fd otherwise. `size` gets its size.
Fd open_regular_file(const std::string& path, FileContents& out, std::size_t& size) {
    Fd fd(open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
    if (fd.get() < 0) {
        out.error = std::strerror(errno);
        return fd;
    }
    struct stat st {};
    if (fstat(fd.get(), &st) != 0) out.error = std::strerror(errno);
    else if (S_ISDIR(st.st_mode)) out.error = "it is a directory";
    else if (!S_ISREG(st.st_mode)) out.error = "it is not a regular file (a device, pipe or socket is not read)";
    size = std::size_t(st.st_size);
    return fd;
}

}  // namespace

FileContents read_file_start(const std::string& path, std::size_t max_bytes) {
    FileContents out;
    std::size_t size = 0;
    const Fd fd = open_regular_file(path, out, size);
    if (!out.error.empty()) return out;
    out.bytes.resize(std::min(size, max_bytes));
    std::size_t have = 0;
    while (have < out.bytes.size()) {
        const ssize_t n = read(fd.get(), out.bytes.data() + have, out.bytes.size() - have);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            out.error = std::strerror(errno);
            return out;
        }
        if (n == 0) break;
        have += std::size_t(n);
    }
    out.bytes.resize(have);
    return out;
}

std::string describe_bytes(std::size_t bytes) {
    char buf[64];
    const double b = double(bytes);
    if (bytes < 10'000) std::snprintf(buf, sizeof buf, "%zu bytes", bytes);
    else if (b < 0x1p20) std::snprintf(buf, sizeof buf, "%.1f KiB", b / 0x1p10);
    else if (b < 0x1p30) std::snprintf(buf, sizeof buf, "%.1f MiB", b / 0x1p20);
    else std::snprintf(buf, sizeof buf, "%.1f GiB", b / 0x1p30);
    return buf;
}

FileContents read_regular_file(const std::string& path, std::size_t max_bytes, const std::atomic<bool>* cancel) {
    FileContents out;
    auto stopped = [&] { return out.cancelled = cancel && cancel->load(std::memory_order_relaxed); };
    const Fd fd(open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
    if (fd.get() < 0) {
        out.error = std::strerror(errno);
        return out;
    }
    struct stat st {};
    if (fstat(fd.get(), &st) != 0) {
        out.error = std::strerror(errno);
        return out;
    }
    if (S_ISDIR(st.st_mode)) {
        out.error = "it is a directory";
        return out;
    }
    if (!S_ISREG(st.st_mode)) {
        out.error = "it is not a regular file (a device, pipe or socket is not read)";
        return out;
    }
    if (std::size_t(st.st_size) > max_bytes) {
        out.error = "it is " + std::to_string(st.st_size) + " bytes, more than the limit of " + describe_bytes(max_bytes);
        return out;
    }
    out.bytes.resize(std::size_t(st.st_size));
    std::size_t have = 0;
    constexpr std::size_t kChunk = std::size_t(1) << 20;
    for (;;) {
        if (stopped()) return out;
        if (have == out.bytes.size()) {
            if (have >= max_bytes) break;  // one byte more would be over: check that the file ended
            out.bytes.resize(std::min(max_bytes, have + kChunk));  // the file grew since fstat
        }
        const ssize_t n = read(fd.get(), out.bytes.data() + have, std::min(kChunk, out.bytes.size() - have));
        if (n < 0) {
            if (errno == EINTR) continue;  // a signal: the loop looks at `cancel` first
            out.error = std::strerror(errno);
            return out;
        }
        if (n == 0) break;
        have += std::size_t(n);
    }
    if (have == max_bytes) {
        char extra;
        ssize_t n;
        while ((n = read(fd.get(), &extra, 1)) < 0 && errno == EINTR) {}
        if (n > 0) {
            out.error = "it grew past the limit of " + describe_bytes(max_bytes) + " while being read";
            return out;
        }
    }
    out.bytes.resize(have);
    return out;
}

}  // namespace whitted
