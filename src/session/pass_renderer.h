#pragma once
// Who renders a pass's tiles for a Session: this process's threads (the default) or, in
// whitted-mpi, the ranks of the job. The session decides what a pass is (its samples, the tiles,
// the pixels still sampling); a PassRenderer only renders them, so every front end gets the same
// passes, time budget, adaptive sampling and partial images.
#include <vector>

#include "film/film.h"
#include "render/render_job.h"
#include "render/renderer.h"

namespace whitted {

class Integrator;

class PassRenderer {
public:
    virtual ~PassRenderer() = default;
    // Renders `tiles` with the job's samples [sample_begin, sample_end) (and job.active's pixels
    // only, when set). Each tile continues from its pixels in `before` (the last whole pass; null
    // in the first pass, which starts from nothing) and ends in `into`; job.on_tile is called with
    // each tile once its pixels are there. Stops early when job.cancel is set (stats.cancelled).
    virtual RenderStats render(const Integrator& integrator, const RenderJob& job, const std::vector<Tile>& tiles,
                               const Film* before, Film& into) = 0;
};

}  // namespace whitted
