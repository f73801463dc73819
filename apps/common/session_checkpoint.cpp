#include "session_checkpoint.h"

#include <iostream>

namespace whitted::cli {

LoadResult load_scene_and_inputs(const RenderOptions& o, const std::atomic<bool>* cancel, std::uint64_t& inputs) {
    LoadOptions lo = load_options(o, cancel);
    if (!uses_checkpoint(o.settings)) return load_scene(o.scene_path, lo);
    // As whitted-mpi's rank 0 loads (the bytes it hashes are the ones parsed), so that either
    // program resumes the other's file.
    const FileContents file = read_scene_file(o.scene_path, lo);
    lo.textures.keep_files = true;
    LoadResult loaded = !file.ok() ? load_scene(o.scene_path, lo) : load_scene_text(file.bytes, o.scene_path, lo);
    inputs = inputs_hash(file.bytes, loaded.texture_files, loaded.mesh_files);
    loaded.texture_files.clear();
    loaded.mesh_files.clear();
    return loaded;
}

int SessionCheckpoint::start(const RenderOptions& o, const LoadResult& loaded, std::uint64_t inputs,
                             Session& session, const char* program) {
    const RenderSettings& s = o.settings;
    program_ = program;
    const RenderJob& job = session.job();
    key_ = {checkpoint_settings(s, job.tile_size), inputs, TileGrid{job.width, job.height, job.tile_size}};
    path_ = s.checkpoint;
    every_ = s.checkpoint_every;
    if (!path_.empty()) {
        // Never written over what the job reads or writes (--checkpoint scene.sc destroyed the scene).
        std::vector<std::string> reads{o.scene_path};
        for (const auto* list : {&loaded.texture_paths, &loaded.mesh_paths})
            reads.insert(reads.end(), list->begin(), list->end());
        reads.insert(reads.end(), s.texture_dirs.begin(), s.texture_dirs.end());
        if (std::string problem = checkpoint_conflict(path_, o.output, reads); !problem.empty()) {
            std::cerr << program_ << ": error: " << problem << "\n";
            return kExitUsage;
        }
    }
    const std::vector<int>& ends = session.pass_ends();
    PassesResumed resumed;
    if (!s.resume.empty()) {
        CheckpointContents contents;
        if (std::string err = read_checkpoint(s.resume, key_, contents, job.cancel); !err.empty()) {
            std::cerr << program_ << ": error: " << err << "\n";
            return err.rfind("interrupted", 0) == 0 ? kExitInterrupted : kExitUsage;
        }
        resumed = passes_resumed(contents, key_.grid, ends);
        session.resume(resumed.passes, resumed.whole, resumed.next, resumed.next_done);
        tiles_resumed_ = resumed.passes * key_.grid.count() + resumed.next_tiles;
        if (!o.quiet) {
            std::cerr << program_ << ": resuming from " << s.resume << ": ";
            if (resumed.passes > 0)
                std::cerr << resumed.passes << " of " << ends.size() << " whole passes ("
                          << ends[std::size_t(resumed.passes - 1)] << " samples per pixel)"
                          << (session.done() ? "" : " and ");
            if (!session.done())
                std::cerr << resumed.next_tiles << " of " << key_.grid.count() << " tiles of the "
                          << (resumed.passes == 0 ? "first pass" : "next");
            std::cerr << "\n";
        }
    }
    if (path_.empty()) return kExitOk;
    std::vector<CheckpointTiles> tiles;
    if (resumed.passes > 0) tiles.push_back({&resumed.whole, {}, ends[std::size_t(resumed.passes - 1)]});
    if (!session.done()) {
        pass_samples_ = ends[std::size_t(session.passes_done())];
        if (resumed.next_tiles > 0) tiles.push_back({&resumed.next, resumed.next_done, pass_samples_});
    }
    if (std::string err = writer_.open(path_, key_, tiles, every_); !err.empty()) {
        std::cerr << program_ << ": error: " << err << "\n";
        return kExitIo;
    }
    return kExitOk;
}

void SessionCheckpoint::tile_done(const Tile& t, const Film& film) {
    if (writer_.is_open()) writer_.append(key_.grid.index_of(t), film, pass_samples_);
}

void SessionCheckpoint::pass_done(const Session& session) {
    if (!writer_.is_open()) return;
    if (std::string err = writer_.open(path_, key_, {{&session.film(), {}, session.samples_done()}}, every_);
        !err.empty())
        // The file keeps the passes before (its records of this one are of no use without it).
        std::cerr << program_ << ": warning: " << err << " (it keeps an earlier pass)\n";
    if (!session.done()) pass_samples_ = session.pass_ends()[std::size_t(session.passes_done())];
}

}  // namespace whitted::cli
