#pragma once
// Per-term images (AOVs): which layers a render writes beside its image, and how each camera
// sample's share (integrator/aov_recorder.h) is added into a ChannelFilm and turned into the
// layers' values. Whitted mode: the terms of the camera ray's hit (ambient, diffuse, specular,
// reflect, transmit, emit, and background where it hit nothing), whose sum is each sample's colour
// before the film clamps it; each light's diffuse, specular and visibility; the hit's normal,
// distance, albedo and object; the samples each pixel took. Path mode: direct and indirect light
// (their sum is the colour), albedo, normal, depth, object, samples.
#include <cstddef>
#include <string>
#include <vector>

#include "film/channel_film.h"
#include "film/film.h"
#include "film/image_layer.h"
#include "integrator/aov_recorder.h"
#include "integrator/render_mode.h"

namespace whitted {

enum class AovKind : unsigned char {
    Ambient, Diffuse, Specular, Reflect, Transmit, Emit, Background,  // Whitted terms
    LightDiffuse, LightSpecular, Shadow,                              // per light
    Direct, Indirect,                                                 // path mode
    Normal, Depth, Albedo, Object, Samples,                           // both
};

struct AovLayer {
    AovKind kind;
    int light = -1;    // per-light layers: which light (0-based; named L1 for the first)
    std::string name;  // "diffuse", "diffuse.L2", "depth": the EXR layer, the PNG file's middle part
    int offset = 0;    // its first float in a ChannelFilm pixel
};

// At most this many layers in one render (per-light layers of a scene with many lights add up).
constexpr std::size_t kMaxAovLayers = 64;

// The comma-separated list of --aov, split (empty names dropped).
std::vector<std::string> split_aov_list(const std::string& list);

// Whether every name of `names` is a layer (or a group of layers: `all`, `shadow`, `diffuse.L*`,
// `specular.L*`) of `mode`, before the scene (and so its lights) is known: "" or the problem.
std::string check_aov_names(const std::vector<std::string>& names, RenderMode mode);

// The layers of one render and where each keeps its floats.
class AovPlan {
public:
    // The layers `names` ask for in `mode` for a scene of `lights` lights, in a fixed order
    // (duplicates once). Returns "" or the problem (a light the scene does not have, too many layers).
    static std::string make(const std::vector<std::string>& names, RenderMode mode, std::size_t lights,
                            AovPlan& out);

    const std::vector<AovLayer>& layers() const { return layers_; }
    int channels() const { return channels_; }  // floats per pixel of the ChannelFilm
    std::size_t lights() const { return lights_; }

    // Adds one camera sample to a pixel's floats. `centre_distance`: how far the sample's point in
    // the pixel is from its centre (the object layer keeps the object of the nearest sample, as
    // the pixel inspector shows it; of equals, the first).
    void add(float* pixel, const AovSample& s, float centre_distance) const;

    // The layers' values over the whole image (pixels outside the films' region 0), one ImageLayer
    // per layer with its EXR channel names. Colour terms and visibility are means over the pixel's
    // samples (film.at(x, y).weight of them, as the image); normal, albedo and depth means over the
    // samples that hit something (depth +inf, normal and albedo 0 where none did); object the id
    // of the nearest sample's object (instance + 1; 0 = background); samples the count.
    std::vector<ImageLayer> resolve(const ChannelFilm& aov, const Film& film) const;

    // The object id of pixel (x, y) (instance + 1; 0 = background).
    static std::uint32_t object_id(const ChannelFilm& aov, int x, int y);

private:
    std::vector<AovLayer> layers_;
    int channels_ = 0;
    std::size_t lights_ = 0;
};

}  // namespace whitted
