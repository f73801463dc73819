#pragma once
// --checkpoint FILE / --resume FILE: the tiles finished so far and their pixels, so that a job
// killed part-way (a dead rank aborts the whole job) is resumed without rendering them again.
// The file is a header and then one record per finished tile, each with its own checksum; it is
// appended to as tiles arrive and flushed to the disk every few seconds. A record cut short by a
// kill is dropped on resume (that tile is rendered again), never read as pixels.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "film/film.h"
#include "tiles.h"

namespace whitted::mpi {

// Everything a checkpoint's pixels depend on: the scene bytes and textures, the options that
// change pixels, the tile grid. A resume with anything else is refused.
struct CheckpointKey {
    std::uint64_t job_hash = 0;
    TileGrid grid;
};

// Reads `path` into `film` (the whole image) and `done` (grid.count() long). Returns "" or why the
// file cannot be used (unreadable, not a checkpoint, made for another job). Read through
// base/read_file.h: a regular file no larger than a checkpoint of this job can be, stopped by
// `cancel`. A bad record (its checksum wrong) is skipped: the next one is looked for where it
// would end, so one damaged tile costs that tile only.
std::string read_checkpoint(const std::string& path, const CheckpointKey& key, Film& film, std::vector<bool>& done,
                            const std::atomic<bool>* cancel = nullptr);

// Why `checkpoint` may not be written by a job that reads `inputs` (the scene file, its textures
// and meshes) and writes `output` (or, interrupted, its NAME.partial.EXT): it is one of them (a
// checkpoint written over the scene destroyed it). "" when it may.
std::string checkpoint_conflict(const std::string& checkpoint, const std::string& output,
                                const std::vector<std::string>& inputs);

class CheckpointWriter {
public:
    ~CheckpointWriter();
    // Starts `path` afresh with the tiles already `done` in `film` (written beside it and renamed
    // over it, so a good file is never lost). Returns "" or an error message.
    std::string open(const std::string& path, const CheckpointKey& key, const Film& film, const std::vector<bool>& done,
                     double flush_seconds);
    bool is_open() const { return file_ != nullptr; }
    void append(int tile, const Film& film);
    // Flushes to the disk when the last flush is flush_seconds old (or `now` is true).
    void flush(bool now = false);

private:
    std::FILE* file_ = nullptr;
    TileGrid grid_;
    double flush_seconds_ = 5;
    std::chrono::steady_clock::time_point last_flush_;
    std::vector<char> buffer_;
};

}  // namespace whitted::mpi
