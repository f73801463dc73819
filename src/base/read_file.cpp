#include "base/read_file.h"

#include <fcntl.h>
#include <linux/openat2.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace whitted {
namespace fs = std::filesystem;
namespace {

class Fd {
public:
    explicit Fd(int fd) : fd_(fd) {}
    ~Fd() {
        if (fd_ >= 0) close(fd_);
    }
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    int get() const { return fd_; }
    int release() {
        const int fd = fd_;
        fd_ = -1;
        return fd;
    }

private:
    int fd_;
};

constexpr int kReadFlags = O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY;

// Set when the kernel has no openat2 (before Linux 5.6), or by the tests.
std::atomic<bool> g_part_by_part{false};

// `path` absolute and normalised, without a trailing separator.
fs::path normalised(const fs::path& path) {
    std::error_code ec;
    fs::path p = fs::absolute(path, ec);
    if (ec) p = path;
    p = p.lexically_normal();
    if (p.has_relative_path() && p.filename().empty()) p = p.parent_path();  // "dir/" → "dir"
    return p;
}

// The part of `path` below `folder` ("." for the folder itself), or "" when it is not below it.
fs::path below(const fs::path& path, const fs::path& folder) {
    auto [f, p] = std::mismatch(folder.begin(), folder.end(), path.begin(), path.end());
    if (f != folder.end()) return {};
    fs::path rest;
    for (; p != path.end(); ++p) rest /= *p;
    return rest.empty() ? fs::path(".") : rest;
}

// Opens `rel` (no `..` in it) beneath the folder `dir` one part at a time, refusing every link.
int open_part_by_part(int dir, const fs::path& rel) {
    std::vector<std::string> parts;
    for (const fs::path& p : rel) parts.push_back(p.string());
    int at = dir, held = -1;
    auto done = [&](int fd) {
        const int saved = errno;
        if (held >= 0) close(held);
        errno = saved;
        return fd;
    };
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
        const int next = openat(at, parts[i].c_str(), O_PATH | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (next < 0) return done(-1);
        done(0);
        held = at = next;
    }
    return done(openat(at, parts.back().c_str(), kReadFlags | O_NOFOLLOW));
}

int open_beneath(int dir, const fs::path& rel) {
    if (!g_part_by_part.load(std::memory_order_relaxed)) {
        open_how how{};
        how.flags = std::uint64_t(kReadFlags);
        how.resolve = RESOLVE_BENEATH | RESOLVE_NO_MAGICLINKS;
        const long fd = syscall(SYS_openat2, dir, rel.c_str(), &how, sizeof how);
        if (fd >= 0 || errno != ENOSYS) return int(fd);
        g_part_by_part.store(true, std::memory_order_relaxed);  // an old kernel: the strict way from now on
    }
    return open_part_by_part(dir, rel);
}

}  // namespace

namespace read_file_testing {
void force_part_by_part(bool on) { g_part_by_part.store(on); }
}  // namespace read_file_testing

Confinement::Confinement(const std::vector<std::string>& folders) {
    for (const std::string& f : folders) {
        Folder folder;
        folder.spelled = normalised(f);
        std::error_code ec;
        folder.real = normalised(fs::weakly_canonical(folder.spelled, ec));
        if (ec) folder.real = folder.spelled;
        folder.fd = open(folder.spelled.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
        if (folder.fd >= 0) folders_.push_back(std::move(folder));
    }
}

Confinement::~Confinement() {
    for (const Folder& f : folders_) close(f.fd);
}

int Confinement::open_inside(const std::string& path) const {
    const fs::path p = normalised(path);
    int inside_error = 0;  // an error about a file inside a folder (no permission, …) is told
    for (const Folder& f : folders_)
        for (const fs::path* base : {&f.spelled, &f.real}) {
            const fs::path rel = below(p, *base);
            if (rel.empty()) continue;
            const int fd = open_beneath(f.fd, rel);
            if (fd >= 0) return fd;
            // Missing, or leading out (EXDEV: `..` or an absolute link; ELOOP: a link refused).
            if (errno != ENOENT && errno != EXDEV && errno != ELOOP && errno != ENOTDIR && !inside_error)
                inside_error = errno;
        }
    errno = inside_error ? inside_error : ENOENT;
    return -1;
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

namespace {

// Opens `path` and checks what was opened (fstat: a regular file, within the limit); on failure
// -1, with out.error (or out.missing) saying why.
int open_checked(const std::string& path, std::size_t max_bytes, const Confinement* inside, FileContents& out) {
    Fd fd(inside ? inside->open_inside(path) : open(path.c_str(), kReadFlags));
    if (fd.get() < 0) {
        out.missing = errno == ENOENT;
        out.error = std::strerror(errno);
        return -1;
    }
    // What was opened is what is checked and read.
    struct stat st {};
    if (fstat(fd.get(), &st) != 0) {
        out.error = std::strerror(errno);
        return -1;
    }
    out.device = std::uint64_t(st.st_dev);
    out.inode = std::uint64_t(st.st_ino);
    if (S_ISDIR(st.st_mode)) {
        out.error = "it is a directory";
        return -1;
    }
    if (!S_ISREG(st.st_mode)) {
        out.error = "it is not a regular file (a device, pipe or socket is not read)";
        return -1;
    }
    if (std::size_t(st.st_size) > max_bytes) {
        out.error = "it is " + std::to_string(st.st_size) + " bytes, more than the limit of " + describe_bytes(max_bytes);
        return -1;
    }
    return fd.release();
}

}  // namespace

FileContents read_regular_file(const std::string& path, std::size_t max_bytes, const std::atomic<bool>* cancel,
                               const Confinement* inside) {
    FileContents out;
    auto stopped = [&] { return out.cancelled = cancel && cancel->load(std::memory_order_relaxed); };
    const Fd fd(open_checked(path, max_bytes, inside, out));
    if (fd.get() < 0) return out;
    struct stat st {};
    if (fstat(fd.get(), &st) != 0) {
        out.error = std::strerror(errno);
        return out;
    }
    out.bytes.resize(std::size_t(st.st_size));
    std::size_t have = 0;
    constexpr std::size_t kChunk = std::size_t(1) << 20;
    for (;;) {
        if (stopped()) return out;
        if (have == out.bytes.size()) {
            if (have >= max_bytes) break;  // one byte more would be over: check that the file ended
            // The size fstat gave is read: whether the file ended is asked with a small buffer, not
            // by growing the string, which would copy the whole text into an allocation twice its
            // size (for a moment both in memory) for a file that nearly always has ended.
            char probe[4096];
            const ssize_t n = read(fd.get(), probe, std::min(sizeof probe, max_bytes - have));
            if (n < 0) {
                if (errno == EINTR) continue;
                out.error = std::strerror(errno);
                return out;
            }
            if (n == 0) break;
            out.bytes.append(probe, std::size_t(n));  // the file grew since fstat
            have += std::size_t(n);
            out.bytes.resize(std::min(max_bytes, have + kChunk));
            continue;
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

FileReader::FileReader(const std::string& path, std::size_t max_bytes, const std::atomic<bool>* cancel,
                       const Confinement* inside)
    : max_bytes_(max_bytes), cancel_(cancel) {
    fd_ = open_checked(path, max_bytes, inside, info_);
}

FileReader::~FileReader() {
    if (fd_ >= 0) close(fd_);
}

std::size_t FileReader::read(char* out, std::size_t n) {
    if (fd_ < 0 || !info_.ok()) return 0;
    if (cancel_ && cancel_->load(std::memory_order_relaxed)) {
        info_.cancelled = true;
        return 0;
    }
    // One byte past the limit is asked for: a file that grew beyond it is refused, not cut short.
    if (at_ > max_bytes_) return 0;  // (sought past the limit: nothing there to read)
    const std::size_t want = max_bytes_ - at_ >= n ? n : max_bytes_ - at_ + 1;
    ssize_t got;
    while ((got = pread(fd_, out, want, off_t(at_))) < 0 && errno == EINTR) {}
    if (got < 0) {
        info_.error = std::strerror(errno);
        return 0;
    }
    at_ += std::size_t(got);
    if (at_ > max_bytes_) {
        info_.error = "it grew past the limit of " + describe_bytes(max_bytes_) + " while being read";
        return 0;
    }
    return std::size_t(got);
}

FileContents read_file_start(const std::string& path, std::size_t max_bytes) {
    FileContents out;
    const Fd fd(open(path.c_str(), kReadFlags));
    if (fd.get() < 0) {
        out.missing = errno == ENOENT;
        out.error = std::strerror(errno);
        return out;
    }
    struct stat st {};
    if (fstat(fd.get(), &st) != 0) out.error = std::strerror(errno);
    else if (S_ISDIR(st.st_mode)) out.error = "it is a directory";
    else if (!S_ISREG(st.st_mode)) out.error = "it is not a regular file (a device, pipe or socket is not read)";
    if (!out.error.empty()) return out;
    out.bytes.resize(std::min(std::size_t(st.st_size), max_bytes));
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

}  // namespace whitted
