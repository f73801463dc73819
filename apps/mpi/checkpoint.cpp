#include "checkpoint.h"

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

#include "base/read_file.h"
#include "film/image_io.h"

namespace whitted::mpi {
namespace {

constexpr char kMagic[8] = {'W', 'H', 'T', 'C', 'K', 'P', 'T', '1'};

struct Header {
    char magic[8];
    std::uint64_t job_hash;
    std::int32_t width, height, tile_size, tile_count;
};

Header header_for(const CheckpointKey& key) {
    Header h{};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.job_hash = key.job_hash;
    h.width = key.grid.width;
    h.height = key.grid.height;
    h.tile_size = key.grid.size;
    h.tile_count = key.grid.count();
    return h;
}

// One record: the tile index, its pixels, and a checksum of both.
void append_record(int tile, const Film& film, const TileGrid& grid, std::vector<char>& out) {
    const std::size_t start = out.size();
    const std::int32_t t = tile;
    out.insert(out.end(), reinterpret_cast<const char*>(&t), reinterpret_cast<const char*>(&t) + sizeof t);
    append_tile_pixels(film, grid.tile(tile), out);
    const std::uint64_t sum = fnv1a(std::string_view(out.data() + start, out.size() - start));
    out.insert(out.end(), reinterpret_cast<const char*>(&sum), reinterpret_cast<const char*>(&sum) + sizeof sum);
}

}  // namespace

std::string read_checkpoint(const std::string& path, const CheckpointKey& key, Film& film, std::vector<bool>& done,
                            const std::atomic<bool>* cancel) {
    const TileGrid& grid = key.grid;
    // The largest a checkpoint of this job can be: its header and every tile once.
    const std::size_t largest = sizeof(Header) + std::size_t(grid.count()) * (sizeof(std::int32_t) + sizeof(std::uint64_t)) +
                                std::size_t(grid.width) * std::size_t(grid.height) * sizeof(FilmPixel);
    const FileContents file = read_regular_file(path, largest, cancel);
    if (file.cancelled) return "interrupted while reading the checkpoint '" + path + "'";
    if (!file.ok())
        return "cannot read the checkpoint '" + path + "': " + file.error +
               (file.error.find("more than the limit") != std::string::npos ? " (no checkpoint of this job is as large)"
                                                                            : "");
    const std::string& bytes = file.bytes;
    Header h{};
    if (bytes.size() < sizeof h) return "'" + path + "' is not a whitted-mpi checkpoint";
    std::memcpy(&h, bytes.data(), sizeof h);
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) return "'" + path + "' is not a whitted-mpi checkpoint";
    const Header want = header_for(key);
    if (h.width != want.width || h.height != want.height || h.tile_size != want.tile_size || h.tile_count != want.tile_count)
        return "the checkpoint '" + path + "' is of a " + std::to_string(h.width) + "x" + std::to_string(h.height) +
               " image in tiles of " + std::to_string(h.tile_size) + "; resume with the options it was made with";
    if (h.job_hash != want.job_hash)
        return "the checkpoint '" + path + "' was made from another scene, textures, meshes or render options";
    done.assign(std::size_t(grid.count()), false);
    const char* const end = bytes.data() + bytes.size();
    Film scratch(grid.width, grid.height);
    // The record at p if it is whole and its checksum right (read into `scratch`): where it ends, else null.
    auto record_at = [&](const char* p, int& tile) -> const char* {
        const char* const record = p;
        if (std::size_t(end - p) < sizeof(std::int32_t)) return nullptr;
        std::int32_t t = 0;
        std::memcpy(&t, p, sizeof t);
        p += sizeof t;
        if (t < 0 || t >= grid.count()) return nullptr;
        std::uint64_t sum = 0;
        if (!read_tile_pixels(p, end, grid.tile(t), scratch) || std::size_t(end - p) < sizeof sum) return nullptr;
        std::memcpy(&sum, p, sizeof sum);
        if (sum != fnv1a(std::string_view(record, std::size_t(p - record)))) return nullptr;
        tile = t;
        return p + sizeof sum;
    };
    // What a record of each size of tile the grid has takes (whole tiles, the last column, the
    // last row, the corner): where the record after a bad one may start.
    std::vector<std::size_t> sizes;
    for (int t : {0, grid.columns() - 1, grid.count() - grid.columns(), grid.count() - 1}) {
        const std::size_t size = sizeof(std::int32_t) + std::size_t(grid.pixels(t)) * sizeof(FilmPixel) + sizeof(std::uint64_t);
        if (std::find(sizes.begin(), sizes.end(), size) == sizes.end()) sizes.push_back(size);
    }
    const char* p = bytes.data() + sizeof h;
    while (p < end) {
        int t = 0;
        const char* next = record_at(p, t);
        for (std::size_t k = 0; !next && k < sizes.size(); ++k)  // a bad record: the next good one after it
            if (sizes[k] < std::size_t(end - p) && (next = record_at(p + sizes[k], t))) p += sizes[k];
        if (!next) break;  // cut short by a kill, or two bad records in a row: the rest is rendered again
        film.copy_from(scratch, grid.tile(t));
        done[std::size_t(t)] = true;
        p = next;
    }
    return "";
}

namespace {

// The same file, or the same place for one that does not exist yet (links followed).
bool same_place(const std::string& a, const std::string& b) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::equivalent(a, b, ec) && !ec) return true;
    const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec), cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
    return !ca.empty() && ca == cb;
}

}  // namespace

std::string checkpoint_conflict(const std::string& checkpoint, const std::string& output,
                                const std::vector<std::string>& inputs) {
    const std::string head = "--checkpoint '" + checkpoint + "' ";
    if (same_place(checkpoint, output)) return head + "is the output image; name another file";
    if (same_place(checkpoint, partial_image_path(output)))
        return head + "is where an interrupted job writes its part (" + partial_image_path(output) + "); name another file";
    for (const std::string& in : inputs)
        if (same_place(checkpoint, in)) return head + "is '" + in + "', which the job reads; name another file";
    return "";
}

CheckpointWriter::~CheckpointWriter() {
    if (file_) {
        flush(true);
        std::fclose(file_);
    }
}

std::string CheckpointWriter::open(const std::string& path, const CheckpointKey& key, const Film& film,
                                   const std::vector<bool>& done, double flush_seconds) {
    grid_ = key.grid;
    flush_seconds_ = flush_seconds;
    const std::string tmp = path + ".tmp" + std::to_string(getpid());
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) return "cannot write the checkpoint '" + tmp + "': " + std::strerror(errno);
    const Header h = header_for(key);
    buffer_.assign(reinterpret_cast<const char*>(&h), reinterpret_cast<const char*>(&h) + sizeof h);
    for (int t = 0; t < grid_.count(); ++t)
        if (done[std::size_t(t)]) append_record(t, film, grid_, buffer_);
    const bool ok = std::fwrite(buffer_.data(), 1, buffer_.size(), f) == buffer_.size() && std::fflush(f) == 0 &&
                    fdatasync(fileno(f)) == 0;
    buffer_.clear();
    std::error_code ec;
    if (ok) std::filesystem::rename(tmp, path, ec);
    if (!ok || ec) {
        std::fclose(f);
        std::filesystem::remove(tmp, ec);
        return "cannot write the checkpoint '" + path + "'";
    }
    file_ = f;  // still open on the renamed file: appends go to `path`
    last_flush_ = std::chrono::steady_clock::now();
    return "";
}

void CheckpointWriter::append(int tile, const Film& film) {
    if (!file_) return;
    append_record(tile, film, grid_, buffer_);
    flush();
}

void CheckpointWriter::flush(bool now) {
    if (!file_) return;
    const auto t = std::chrono::steady_clock::now();
    if (!now && std::chrono::duration<double>(t - last_flush_).count() < flush_seconds_) return;
    last_flush_ = t;
    // Whole records only reach the file, so a kill between flushes cuts no record in two
    // (one cut by a kill during the write is dropped on resume).
    if (!buffer_.empty()) (void)!std::fwrite(buffer_.data(), 1, buffer_.size(), file_);
    buffer_.clear();
    std::fflush(file_);
    fdatasync(fileno(file_));
}

}  // namespace whitted::mpi
