#pragma once
// What an image file says about how it was made (PNG tEXt, EXR attributes): the samples each pixel
// got, in how many of the schedule's passes, and every setting that changed its pixels. The same
// from every front end, so that whitted-mpi's file is byte for byte whitted's.
#include "film/image.h"
#include "session/render_settings.h"

namespace whitted {

ImageText render_image_text(const RenderSettings& settings, int samples, int passes_done, int passes_total);

}  // namespace whitted
