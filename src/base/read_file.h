#pragma once
// The one door every file someone else may have named comes through (scene files, textures,
// meshes, checkpoints): only a regular file (a device such as /dev/zero would never end, a FIFO
// would block), no more than a size limit, stoppable, and — for files from others — only from
// inside the folders allowed. The file is opened first and what was opened is checked (fstat),
// never a name checked and then opened again: a link or a FIFO swapped in between changes nothing.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace whitted {

struct FileContents {
    std::string bytes;
    std::string error;       // why the file cannot be had ("it is a directory", strerror, …), or ""
    bool missing = false;    // nothing there; for a confined read also: nothing the folders reach
    bool cancelled = false;  // the cancel flag was set while reading
    std::uint64_t device = 0, inode = 0;  // of the file opened (two names of one file read alike)
    bool ok() const { return error.empty() && !cancelled; }
};

// The folders a confined read may reach (--untrusted: the scene's folder, --texture-path). Each is
// opened once, here (following links: the user named it); a read then resolves the rest of its
// path beneath that open folder in one system call (openat2 with RESOLVE_BENEATH), so that `..`,
// an absolute link or a link swapped in while it runs cannot lead out. Links that stay inside are
// followed (where the kernel lacks openat2, no link is: each part is opened with O_NOFOLLOW).
class Confinement {
public:
    explicit Confinement(const std::vector<std::string>& folders);
    ~Confinement();
    Confinement(const Confinement&) = delete;
    Confinement& operator=(const Confinement&) = delete;

    // Opens `path` for reading if it lies inside one of the folders, else returns -1 with errno
    // ENOENT (missing and outside are not told apart: a file from others must not learn which
    // paths exist outside). The caller closes the descriptor.
    int open_inside(const std::string& path) const;

private:
    struct Folder {
        std::filesystem::path spelled, real;  // as given (absolute, normalised), and resolved
        int fd = -1;
    };
    std::vector<Folder> folders_;
};

// Opens without blocking (a FIFO with no writer does not hang it), refuses anything but a regular
// file, and a file over `max_bytes` before reading a byte of it; reads in chunks, looking at
// `cancel` between them. With `inside`, only a file inside its folders is opened.
FileContents read_regular_file(const std::string& path, std::size_t max_bytes,
                               const std::atomic<bool>* cancel = nullptr, const Confinement* inside = nullptr);

// The same door for a file used a piece at a time, never held whole (a mesh's text: a 1M-triangle
// OBJ is 40 to 100 MB, as much as the mesh made of it): opened and checked as read_regular_file
// opens and checks (info() says why not, with `bytes` always empty), then read in order.
class FileReader {
public:
    FileReader(const std::string& path, std::size_t max_bytes, const std::atomic<bool>* cancel = nullptr,
               const Confinement* inside = nullptr);
    ~FileReader();
    FileReader(const FileReader&) = delete;
    FileReader& operator=(const FileReader&) = delete;

    const FileContents& info() const { return info_; }
    bool ok() const { return info_.ok(); }
    // Up to `n` bytes from where the last read ended into `out`: 0 at the end of the file, and
    // when it cannot go on (info() then says why: an error, the cancel flag, or the file grew
    // past the size limit while being read).
    std::size_t read(char* out, std::size_t n);
    // Where the next read starts (the same file: what was opened is what is read again).
    std::size_t position() const { return at_; }
    void seek(std::size_t at) { at_ = at; }

private:
    FileContents info_;
    int fd_ = -1;
    std::size_t max_bytes_;
    const std::atomic<bool>* cancel_;
    std::size_t at_ = 0;
};

// The first (up to) `max_bytes` bytes of a regular file, whatever its size: enough to tell what
// kind of file it is without reading all of it. Refuses what read_regular_file refuses.
FileContents read_file_start(const std::string& path, std::size_t max_bytes);

// "4800 bytes", "12.3 MiB", "1.5 GiB": sizes for messages.
std::string describe_bytes(std::size_t bytes);

namespace read_file_testing {
// Makes Confinement open part by part with O_NOFOLLOW, as on a kernel without openat2.
void force_part_by_part(bool on);
}  // namespace read_file_testing

}  // namespace whitted
