#pragma once
// How to render: the method and its recursion limit. Settings only, so that whatever describes a
// render (render/render_job.h) names them without pulling in an integrator.
#include "integrator/render_mode.h"

namespace whitted {

struct IntegratorSettings {
    RenderMode mode = RenderMode::Whitted;
    int max_depth = 5;  // camera ray = depth 0; no ray deeper than this is traced (path: bounces)
};

}  // namespace whitted
