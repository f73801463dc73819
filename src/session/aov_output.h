#pragma once
// Writing a render's per-term images (render/aov.h) beside its image: one multi-layer OpenEXR
// file (the image's R, G, B and every layer's channels, "diffuse.R", "depth.Z", as Blender and
// Nuke read them), or one PNG per layer. In a PNG the colour layers are 8-bit as the image is
// (§7: clamped, no gamma); the others are mapped so they can be looked at:
//   normal   each component n ↦ (n + 1)/2 (the usual normal-map colours; no hit: mid grey)
//   depth    grey, distance / the farthest distance in the image (its value in the file's text
//            "depth max"); no hit: white
//   object   a colour per object, black for the background; the file's text "objects" lists
//            each id, its colour and its object's FILE:LINE
//   samples  grey, samples / the most any pixel took (text "samples max")
// The ids of the object layer (instance + 1; 0 = background) and their FILE:LINE go into the text
// "objects" of the EXR file or the object PNG: one line each, "ID FILE:LINE", for the ids in the image.
#include <string>

#include "film/image.h"
#include "film/image_layer.h"
#include "render/aov.h"

namespace whitted {

class Session;
struct Scene;

// Writes the session's image to `image_path` (.exr and .pfm linear, the others 8-bit, with `text`)
// and its layers: into one .exr with the image's channels when `aov_file` is .exr, or when it is
// empty and the image is .exr; else one PNG per layer named after `aov_file` (or the image):
// NAME.LAYER.png. Returns "" or the first error.
std::string write_image_with_aovs(const Session& session, const std::string& image_path, const std::string& aov_file,
                                  const ImageText& text);

// Where layer `layer`'s PNG goes for `base` (dir/NAME.EXT → dir/NAME.LAYER.png).
std::string aov_png_path(const std::string& base, const std::string& layer);

// "ID FILE:LINE" lines for the ids the object layer holds (width·height values), in id order.
std::string object_table(const Scene& scene, const ImageLayer& object_layer);

// The 8-bit picture of one layer as its PNG shows it (above), with its text.
Image aov_png_image(const Scene& scene, const AovLayer& layer, const ImageLayer& values, int width, int height);

}  // namespace whitted
