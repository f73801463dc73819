#include "session/checkpoint.h"

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <utility>

#include "base/read_file.h"
#include "film/image_io.h"

namespace whitted {
namespace {

constexpr char kMagic[8] = {'W', 'H', 'T', 'C', 'K', 'P', 'T', '2'};
constexpr std::size_t kMaxSettings = std::size_t(1) << 16;  // far more than the table's text

// Followed by the settings text and a checksum of both.
struct Header {
    char magic[8];
    std::int32_t width, height, tile_size, tile_count;
    std::uint64_t inputs;
    std::uint32_t settings_length, reserved;
};
static_assert(sizeof(Header) == 40);

template <class T>
void put(std::vector<char>& out, const T& value) {
    out.insert(out.end(), reinterpret_cast<const char*>(&value), reinterpret_cast<const char*>(&value) + sizeof value);
}

std::vector<char> header_bytes(const CheckpointKey& key) {
    Header h{};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.width = key.grid.width;
    h.height = key.grid.height;
    h.tile_size = key.grid.size;
    h.tile_count = key.grid.count();
    h.inputs = key.inputs;
    h.settings_length = std::uint32_t(key.settings.size());
    const std::size_t text_end = sizeof h + key.settings.size();
    std::vector<char> out(text_end + sizeof(std::uint64_t));
    std::memcpy(out.data(), &h, sizeof h);
    std::memcpy(out.data() + sizeof h, key.settings.data(), key.settings.size());
    const std::uint64_t sum = fnv1a(std::string_view(out.data(), text_end));
    std::memcpy(out.data() + text_end, &sum, sizeof sum);
    return out;
}

// One record: the tile index, its samples per pixel, its pixels, and a checksum of them all.
constexpr std::size_t kRecordOverhead = 2 * sizeof(std::int32_t) + sizeof(std::uint64_t);

void append_record(int tile, int samples, const Film& film, const TileGrid& grid, std::vector<char>& out) {
    const std::size_t start = out.size();
    put(out, std::int32_t(tile));
    put(out, std::int32_t(samples));
    append_tile_pixels(film, grid.tile(tile), out);
    put(out, fnv1a(std::string_view(out.data() + start, out.size() - start)));
}

// "name=value;" pairs.
std::vector<std::pair<std::string, std::string>> settings_pairs(std::string_view text) {
    std::vector<std::pair<std::string, std::string>> out;
    while (!text.empty()) {
        const std::size_t end = std::min(text.find(';'), text.size());
        const std::string_view item = text.substr(0, end);
        const std::size_t eq = item.find('=');
        if (eq != std::string_view::npos) out.emplace_back(item.substr(0, eq), item.substr(eq + 1));
        text.remove_prefix(std::min(text.size(), end + 1));
    }
    return out;
}

// "--time 0, not 0.5": the first setting whose value differs, as the user would write it.
std::string setting_difference(const std::string& made, const std::string& now) {
    const auto now_pairs = settings_pairs(now);
    auto shown = [](const std::string& v) { return v.empty() ? std::string("(none)") : v; };
    for (const auto& pair : settings_pairs(made)) {
        const std::string& name = pair.first;  // not a structured binding: clang before 16 cannot capture one
        const std::string& value = pair.second;
        const auto it = std::find_if(now_pairs.begin(), now_pairs.end(), [&](const auto& p) { return p.first == name; });
        if (it == now_pairs.end()) return "";
        if (it->second != value)
            return "--" + (name == "tile" ? std::string("tile-size") : name) + " " + shown(value) + ", not " +
                   shown(it->second);
    }
    return "";
}

}  // namespace

std::string checkpoint_settings(const RenderSettings& s, int tile_size) {
    return pixel_key(s) + "tile=" + std::to_string(tile_size) + ";";
}

std::uint64_t inputs_hash(std::string_view scene_text, const TextureFiles& textures, const TextureFiles& meshes) {
    // Each piece as its 8-byte length and its bytes; a list as its count (as text) and its files'
    // names and bytes.
    std::uint64_t h = fnv1a({});
    auto piece = [&h](std::string_view bytes) {
        const std::uint64_t n = bytes.size();
        h = fnv1a(std::string_view(reinterpret_cast<const char*>(&n), sizeof n), h);
        h = fnv1a(bytes, h);
    };
    piece(scene_text);
    for (const TextureFiles* files : {&textures, &meshes}) {
        piece(std::to_string(files->size()));
        for (const auto& [name, bytes] : *files) {
            piece(name);
            piece(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        }
    }
    return h;
}

int CheckpointContents::tiles_at(int samples) const {
    std::vector<bool> seen(std::size_t(grid_.count()), false);
    for (const Record& r : records_)
        if (r.samples == samples) seen[std::size_t(r.tile)] = true;
    return int(std::count(seen.begin(), seen.end(), true));
}

void CheckpointContents::load(int samples, Film& film, std::vector<bool>& done) const {
    done.resize(std::size_t(grid_.count()), false);
    for (const Record& r : records_) {
        if (r.samples != samples) continue;
        const char* p = bytes_.data() + r.pixels;
        read_tile_pixels(p, bytes_.data() + bytes_.size(), grid_.tile(r.tile), film);
        done[std::size_t(r.tile)] = true;
    }
}

std::string read_checkpoint(const std::string& path, const CheckpointKey& key, CheckpointContents& out,
                            const std::atomic<bool>* cancel) {
    const TileGrid& grid = key.grid;
    // The largest a checkpoint of this job can be: its header and every tile twice (a whole pass
    // and the pass after it).
    const std::size_t all_tiles = std::size_t(grid.count()) * kRecordOverhead +
                                  std::size_t(grid.width) * std::size_t(grid.height) * sizeof(FilmPixel);
    const std::size_t largest = sizeof(Header) + kMaxSettings + sizeof(std::uint64_t) + 2 * all_tiles;
    FileContents file = read_regular_file(path, largest, cancel);
    if (file.cancelled) return "interrupted while reading the checkpoint '" + path + "'";
    if (!file.ok())
        return "cannot read the checkpoint '" + path + "': " + file.error +
               (file.error.find("more than the limit") != std::string::npos ? " (no checkpoint of this job is as large)"
                                                                            : "");
    out.bytes_ = std::move(file.bytes);
    out.records_.clear();
    out.grid_ = grid;
    const std::string& bytes = out.bytes_;
    const std::string not_one = "'" + path + "' is not a whitted checkpoint";
    Header h{};
    if (bytes.size() < sizeof h) return not_one;
    std::memcpy(&h, bytes.data(), sizeof h);
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0) return not_one;
    std::uint64_t sum = 0;
    const std::size_t header_end = sizeof h + std::size_t(h.settings_length);
    if (h.settings_length > kMaxSettings || bytes.size() < header_end + sizeof sum)
        return "the checkpoint '" + path + "' is damaged (its header is cut short)";
    std::memcpy(&sum, bytes.data() + header_end, sizeof sum);
    if (sum != fnv1a(std::string_view(bytes.data(), header_end)))
        return "the checkpoint '" + path + "' is damaged (its header's checksum is wrong)";
    const std::string settings = bytes.substr(sizeof h, h.settings_length);
    if (h.width != grid.width || h.height != grid.height || h.tile_size != grid.size || h.tile_count != grid.count())
        return "the checkpoint '" + path + "' is of a " + std::to_string(h.width) + "x" + std::to_string(h.height) +
               " image in tiles of " + std::to_string(h.tile_size) + "; resume with the options it was made with";
    if (settings != key.settings) {
        const std::string which = setting_difference(settings, key.settings);
        return "the checkpoint '" + path + "' was made with " + (which.empty() ? "other render options" : which) +
               "; resume with the options it was made with";
    }
    if (h.inputs != key.inputs)
        return "the checkpoint '" + path +
               "' was made from another scene, textures or meshes (a file changed since); render without --resume";

    const char* const begin = bytes.data();
    const char* const end = begin + bytes.size();
    Film scratch(grid.width, grid.height);  // read_tile_pixels' target while a record is checked
    // The record at p if it is whole and its checksum right: where it ends, else null.
    auto record_at = [&](const char* p, CheckpointContents::Record& r) -> const char* {
        const char* const record = p;
        if (std::size_t(end - p) < 2 * sizeof(std::int32_t)) return nullptr;
        std::int32_t t = 0, samples = 0;
        std::memcpy(&t, p, sizeof t);
        std::memcpy(&samples, p + sizeof t, sizeof samples);
        p += 2 * sizeof t;
        if (t < 0 || t >= grid.count() || samples <= 0) return nullptr;
        const char* const pixels = p;
        std::uint64_t check = 0;
        if (!read_tile_pixels(p, end, grid.tile(t), scratch) || std::size_t(end - p) < sizeof check) return nullptr;
        std::memcpy(&check, p, sizeof check);
        if (check != fnv1a(std::string_view(record, std::size_t(p - record)))) return nullptr;
        r = {t, samples, std::size_t(pixels - begin)};
        return p + sizeof check;
    };
    // What a record of each size of tile the grid has takes (whole tiles, the last column, the
    // last row, the corner): where the record after a bad one may start.
    std::vector<std::size_t> sizes;
    for (int t : {0, grid.columns() - 1, grid.count() - grid.columns(), grid.count() - 1}) {
        const std::size_t size = kRecordOverhead + std::size_t(grid.pixels(t)) * sizeof(FilmPixel);
        if (std::find(sizes.begin(), sizes.end(), size) == sizes.end()) sizes.push_back(size);
    }
    const char* p = begin + header_end + sizeof sum;
    while (p < end) {
        CheckpointContents::Record r{};
        const char* next = record_at(p, r);
        for (std::size_t k = 0; !next && k < sizes.size(); ++k)  // a bad record: the next good one after it
            if (sizes[k] < std::size_t(end - p) && (next = record_at(p + sizes[k], r))) p += sizes[k];
        if (!next) break;  // cut short by a kill, or two bad records in a row: the rest is rendered again
        out.records_.push_back(r);
        p = next;
    }
    return "";
}

std::string read_checkpoint(const std::string& path, const CheckpointKey& key, int samples, Film& film,
                            std::vector<bool>& done, const std::atomic<bool>* cancel) {
    CheckpointContents contents;
    done.assign(std::size_t(key.grid.count()), false);
    if (std::string err = read_checkpoint(path, key, contents, cancel); !err.empty()) return err;
    contents.load(samples, film, done);
    return "";
}

PassesResumed passes_resumed(const CheckpointContents& contents, const TileGrid& grid,
                             const std::vector<int>& pass_ends) {
    PassesResumed r;
    for (int k = int(pass_ends.size()); k > 0 && r.passes == 0; --k)
        if (contents.tiles_at(pass_ends[std::size_t(k - 1)]) == grid.count()) r.passes = k;
    if (r.passes > 0) {
        r.whole.reset(grid.width, grid.height, {0, 0, grid.width, grid.height});
        std::vector<bool> all;
        contents.load(pass_ends[std::size_t(r.passes - 1)], r.whole, all);
    }
    r.next_done.assign(std::size_t(grid.count()), false);
    if (r.passes < int(pass_ends.size())) {
        r.next.reset(grid.width, grid.height, {0, 0, grid.width, grid.height});
        contents.load(pass_ends[std::size_t(r.passes)], r.next, r.next_done);
        r.next_tiles = int(std::count(r.next_done.begin(), r.next_done.end(), true));
    }
    return r;
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
    std::lock_guard lock(mutex_);
    close_locked();
}

void CheckpointWriter::close_locked() {
    if (!file_) return;
    flush_locked(true);
    std::fclose(file_);
    file_ = nullptr;
}

std::string CheckpointWriter::open(const std::string& path, const CheckpointKey& key,
                                   const std::vector<CheckpointTiles>& tiles, double flush_seconds) {
    std::lock_guard lock(mutex_);
    const std::string tmp = path + ".tmp" + std::to_string(getpid());
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) return "cannot write the checkpoint '" + tmp + "': " + std::strerror(errno);
    std::vector<char> bytes = header_bytes(key);
    for (const CheckpointTiles& set : tiles)
        for (int t = 0; t < key.grid.count(); ++t)
            if (set.done.empty() || set.done[std::size_t(t)]) append_record(t, set.samples, *set.film, key.grid, bytes);
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size() && std::fflush(f) == 0 &&
                    fdatasync(fileno(f)) == 0;
    std::error_code ec;
    if (ok) std::filesystem::rename(tmp, path, ec);
    if (!ok || ec) {
        std::fclose(f);
        std::filesystem::remove(tmp, ec);
        return "cannot write the checkpoint '" + path + "'";
    }
    // The records not yet flushed to the file replaced belong to it (they are in the new one, or
    // of a pass the new one holds whole).
    buffer_.clear();
    if (file_) std::fclose(file_);  // the file replaced
    file_ = f;  // still open on the renamed file: appends go to `path`
    grid_ = key.grid;
    flush_seconds_ = flush_seconds;
    last_flush_ = std::chrono::steady_clock::now();
    return "";
}

void CheckpointWriter::append(int tile, const Film& film, int samples) {
    std::lock_guard lock(mutex_);
    if (!file_) return;
    append_record(tile, samples, film, grid_, buffer_);
    flush_locked(false);
}

void CheckpointWriter::flush(bool now) {
    std::lock_guard lock(mutex_);
    flush_locked(now);
}

void CheckpointWriter::flush_locked(bool now) {
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

}  // namespace whitted
