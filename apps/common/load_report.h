#pragma once
// What the command-line renderers print about a load and a render: the scene's diagnostics (with
// the exit code they mean) and the --stats lines.
#include "render/load_scene.h"
#include "render/renderer.h"
#include "render_options.h"

namespace whitted::cli {

// Prints the load's warnings and errors to stderr. Returns kExitOk when there is a scene to
// render, else the code to exit with (interrupted, --timeout ran out, bad scene, unreadable file).
// `limit` names the time limit that ran out, if one did ("--timeout", "--time-limit"; null: none).
int report_load(const LoadResult& loaded, const RenderOptions& o, const char* program, const char* limit = nullptr);

// The --stats lines of a load and a render (samples per pixel reached, in how many passes).
void print_stats(const LoadStats& ls, const RenderStats& rs, int samples_per_pixel, int passes = 1);
// Its lines of the rays traced in `seconds`: how many of each kind, and each kind's rate through
// the acceleration structure (whitted-mpi's for all its ranks).
void print_rays(const RayCounts& rays, double seconds);

}  // namespace whitted::cli
