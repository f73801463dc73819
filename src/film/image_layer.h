#pragma once
// Channels an OpenEXR file keeps beside an image's R, G and B: the per-term images of a render
// (diffuse, depth, ...), named as Blender and Nuke read a multi-layer file ("diffuse.R",
// "depth.Z": the layer, a dot, the channel).
#include <string>
#include <vector>

namespace whitted {

struct ImageLayer {
    std::vector<std::string> channels;  // full names, "diffuse.R"
    std::vector<float> values;          // width·height·channels.size(), pixel after pixel, row 0 at the top
};

}  // namespace whitted
