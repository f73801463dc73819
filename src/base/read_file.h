#pragma once
// Reading a file someone else may have named: only a regular file (a device such as /dev/zero
// would never end, a FIFO would block), no more than a size limit, and stoppable.
#include <atomic>
#include <cstddef>
#include <string>

namespace whitted {

struct FileContents {
    std::string bytes;
    std::string error;       // why the file cannot be had ("it is a directory", strerror, …), or ""
    bool cancelled = false;  // the cancel flag was set while reading
    bool ok() const { return error.empty() && !cancelled; }
};

// Opens without blocking (a FIFO with no writer does not hang it), refuses anything but a regular
// file, and a file over `max_bytes` before reading a byte of it; reads in chunks, looking at
// `cancel` between them.
FileContents read_regular_file(const std::string& path, std::size_t max_bytes,
                               const std::atomic<bool>* cancel = nullptr);

// The first (up to) `max_bytes` bytes of a regular file, whatever its size: enough to tell what
// kind of file it is without reading all of it. Refuses what read_regular_file refuses.
FileContents read_file_start(const std::string& path, std::size_t max_bytes);

// "4800 bytes", "12.3 MiB", "1.5 GiB": sizes for messages.
std::string describe_bytes(std::size_t bytes);

}  // namespace whitted
