#pragma once
// Image-space driver: cuts the job's region into tiles, hands them to worker threads (each with
// its own TileRenderer), and stops when asked. Every pixel depends only on its own coordinates
// and sample indices, so the image is the same for any thread count and tile size.
#include <functional>
#include <vector>

#include "film/film.h"
#include "film/image.h"
#include "integrator/integrator.h"
#include "render/render_job.h"

namespace whitted {

struct RenderStats {
    RayCounts rays;
    double seconds = 0;
    int tiles_done = 0, tiles_total = 0;
    int threads = 0;  // worker threads used (never more than there are tiles)
    bool cancelled = false;  // pixels of unfinished tiles keep the samples they had
};

// Adds the job's samples of its region to `film` (of the job's size, covering the region) through
// `integrator`, which sees the scene through the camera it was made with.
RenderStats render(const Integrator& integrator, const RenderJob& job, Film& film);

// The same for the given tiles of the job's image (each inside the film's region, at most
// job.tile_size on a side), spread over the job's threads: how a share handed out by another
// machine is rendered.
RenderStats render_tiles(const Integrator& integrator, const RenderJob& job, const std::vector<Tile>& tiles,
                         Film& film);

// The same, each tile's samples added to the film film_for(tile) gives (called on the worker that
// renders the tile, before it does): a render session's passes continue each tile from the last.
RenderStats render_tiles_into(const Integrator& integrator, const RenderJob& job, const std::vector<Tile>& tiles,
                              const std::function<Film&(const Tile&)>& film_for);

// The job's region cut into tiles of tile_size (the last ones of a row and column smaller), row by row.
std::vector<Tile> cut_into_tiles(const PixelRegion& region, int tile_size);

// The common case: the job's integrator on the job's camera, the whole image, into `image` (of the
// job's size; pixels of tiles not reached before a cancel are left black).
RenderStats render(const Scene& scene, const RenderJob& job, Image& image);

}  // namespace whitted
