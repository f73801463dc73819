#pragma once
// --checkpoint FILE / --resume FILE (whitted and whitted-mpi): the pixels rendered so far, so that a
// job stopped part-way (a reboot, a killed rank, a batch system's limit) is resumed without
// rendering them again, to the bytes an uninterrupted job writes.
//
// The file is a header (the key: the image and tile size, the settings that change pixels as text,
// a hash of the input bytes) and then records, one tile each: its index, the samples per pixel its
// pixels hold, the pixels as the film keeps them (sums and weights), a checksum. whitted-mpi
// appends each tile once it has all its samples; whitted, which renders in passes over the whole
// image, appends the tiles of the pass under way and, after each whole pass, starts the file
// afresh with every tile of it. A file is only ever replaced whole (written beside and renamed);
// records are flushed to the disk every few seconds, and one cut short by a kill, or damaged, is
// dropped on resume (that tile is rendered again), never read as pixels.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "film/film.h"
#include "render/load_scene.h"
#include "session/render_settings.h"
#include "session/tile_grid.h"

namespace whitted {

// Everything a checkpoint's pixels depend on. A resume with anything else is refused.
struct CheckpointKey {
    std::string settings;      // checkpoint_settings(): "name=value;" of what changes pixels
    std::uint64_t inputs = 0;  // inputs_hash(): the scene's bytes, its textures' and meshes'
    TileGrid grid;
};

// The key's settings: every setting of the table that changes pixels, and the tile size.
std::string checkpoint_settings(const RenderSettings& s, int tile_size);

// A hash of every input byte of a job: the scene text and each texture and mesh file, by name
// (the value whitted-mpi's broadcast of them hashes to, so that both take each other's files).
std::uint64_t inputs_hash(std::string_view scene_text, const TextureFiles& textures, const TextureFiles& meshes);

// The good records of a checkpoint file.
class CheckpointContents {
public:
    // How many tiles are stored with `samples` samples per pixel.
    int tiles_at(int samples) const;
    // Copies those tiles into `film` (the whole image) and marks them in `done` (grid.count() long).
    void load(int samples, Film& film, std::vector<bool>& done) const;

private:
    friend std::string read_checkpoint(const std::string&, const CheckpointKey&, CheckpointContents&,
                                       const std::atomic<bool>*);
    struct Record {
        int tile, samples;
        std::size_t pixels;  // where its pixels start in bytes_
    };
    std::string bytes_;
    std::vector<Record> records_;
    TileGrid grid_;
};

// Reads `path` into `out`. Returns "" or why the file cannot be used: unreadable, not a checkpoint,
// made for another job (saying which setting differs, or that the input files do). Read through
// base/read_file.h: a regular file no larger than a checkpoint of this job can be, stopped by
// `cancel`. A bad record (its checksum wrong) is skipped: the next one is looked for where it
// would end, so one damaged tile costs that tile only.
std::string read_checkpoint(const std::string& path, const CheckpointKey& key, CheckpointContents& out,
                            const std::atomic<bool>* cancel = nullptr);

// The same, keeping only the tiles of `samples` samples per pixel (whitted-mpi: the job's all).
std::string read_checkpoint(const std::string& path, const CheckpointKey& key, int samples, Film& film,
                            std::vector<bool>& done, const std::atomic<bool>* cancel = nullptr);

// Where a render in passes (session/session.h) stands in a checkpoint: the most whole passes it
// holds (every tile at that pass's samples), in `whole`, and the tiles it holds of the pass after
// them, in `next`. `pass_ends` is the sample count each pass ends at (Session::pass_ends()).
struct PassesResumed {
    int passes = 0;
    Film whole, next;
    std::vector<bool> next_done;
    int next_tiles = 0;
};
PassesResumed passes_resumed(const CheckpointContents& contents, const TileGrid& grid,
                             const std::vector<int>& pass_ends);

// Why `checkpoint` may not be written by a job that reads `inputs` (the scene file, its textures
// and meshes) and writes `output` (or, interrupted, its NAME.partial.EXT): it is one of them (a
// checkpoint written over the scene destroyed it). "" when it may.
std::string checkpoint_conflict(const std::string& checkpoint, const std::string& output,
                                const std::vector<std::string>& inputs);

// Tiles to start a checkpoint file with: those `done` marks (empty: every tile) of `film`, holding
// `samples` samples per pixel.
struct CheckpointTiles {
    const Film* film = nullptr;
    std::vector<bool> done;
    int samples = 0;
};

class CheckpointWriter {
public:
    ~CheckpointWriter();
    // Starts `path` afresh with `tiles` (written beside it and renamed over it, so a good file is
    // never lost); appends then go to it. Returns "" or an error message (the file open before,
    // if any, then stays the one appended to).
    std::string open(const std::string& path, const CheckpointKey& key, const std::vector<CheckpointTiles>& tiles,
                     double flush_seconds);
    bool is_open() const { return file_ != nullptr; }
    // Appends tile `tile` of `film`, holding `samples` samples per pixel. Safe to call from several
    // threads at once (each reading its own tile of the film).
    void append(int tile, const Film& film, int samples);
    // Flushes to the disk when the last flush is flush_seconds old (or `now` is true).
    void flush(bool now = false);

private:
    void flush_locked(bool now);
    void close_locked();

    std::mutex mutex_;
    std::FILE* file_ = nullptr;
    TileGrid grid_;
    double flush_seconds_ = 5;
    std::chrono::steady_clock::time_point last_flush_;
    std::vector<char> buffer_;
};

}  // namespace whitted
