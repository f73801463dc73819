#include "checkpoint.h"

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

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

std::string read_checkpoint(const std::string& path, const CheckpointKey& key, Film& film, std::vector<bool>& done) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "cannot read the checkpoint '" + path + "'";
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Header h{};
    if (bytes.size() < sizeof h) return "'" + path + "' is not a whitted-mpi checkpoint";
    std::memcpy(&h, bytes.data(), sizeof h);
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) return "'" + path + "' is not a whitted-mpi checkpoint";
    const Header want = header_for(key);
    if (h.width != want.width || h.height != want.height || h.tile_size != want.tile_size || h.tile_count != want.tile_count)
        return "the checkpoint '" + path + "' is of a " + std::to_string(h.width) + "x" + std::to_string(h.height) +
               " image in tiles of " + std::to_string(h.tile_size) + "; resume with the options it was made with";
    if (h.job_hash != want.job_hash)
        return "the checkpoint '" + path + "' was made from another scene, textures or render options";
    done.assign(std::size_t(key.grid.count()), false);
    const char* p = bytes.data() + sizeof h;
    const char* end = bytes.data() + bytes.size();
    Film scratch(key.grid.width, key.grid.height);
    while (std::size_t(end - p) >= sizeof(std::int32_t)) {
        const char* record = p;
        std::int32_t t = 0;
        std::memcpy(&t, p, sizeof t);
        p += sizeof t;
        if (t < 0 || t >= key.grid.count()) break;
        const Tile r = key.grid.tile(t);
        std::uint64_t sum = 0;
        if (!read_tile_pixels(p, end, r, scratch) || std::size_t(end - p) < sizeof sum) break;  // cut short
        std::memcpy(&sum, p, sizeof sum);
        if (sum != fnv1a(std::string_view(record, std::size_t(p - record)))) break;
        p += sizeof sum;
        film.copy_from(scratch, r);
        done[std::size_t(t)] = true;
    }
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
