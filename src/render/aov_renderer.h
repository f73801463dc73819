#pragma once
// Rendering with per-term images (render/aov.h): the tiles' samples one camera ray at a time
// through the integrator's recording entry (Whitted: the AOV recorder; path: the direct part),
// each colour added to the film as the renderer adds it (the same colours, in the same order:
// the image is the one a render without layers gives) and each sample's layers to a ChannelFilm.
// Only a render that asks for layers comes here; the renderer's own loop is untouched.
#include <functional>
#include <string>
#include <vector>

#include "film/channel_film.h"
#include "film/film.h"
#include "integrator/integrator.h"
#include "render/aov.h"
#include "render/render_job.h"
#include "render/renderer.h"

namespace whitted {

// Why `integrator` cannot record layers, or "" (Whitted and path tracing can; the course's model
// of a CSCI 1230 scene and the debug views cannot).
std::string aov_refusal(const Integrator& integrator);

// As render_tiles_into (render/renderer.h), each tile's colours into film_for(tile) and its layers
// into aov_for(tile) (of plan.channels() floats a pixel). Adaptive anti-aliasing is not supported
// (the caller refuses it).
RenderStats render_tiles_with_aovs(const Integrator& integrator, const RenderJob& job, const AovPlan& plan,
                                   const std::vector<Tile>& tiles, const std::function<Film&(const Tile&)>& film_for,
                                   const std::function<ChannelFilm&(const Tile&)>& aov_for);

}  // namespace whitted
