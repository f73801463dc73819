#pragma once
// SceneDescription (a graph of mastersubgraphs) → SceneData (one Instance per drawn object).
#include <atomic>
#include <cstddef>
#include <vector>

#include "data/scene_data.h"
#include "base/diagnostic.h"
#include "description/scene_description.h"

namespace whitted {

struct FlattenResult {
    SceneData scene;
    // One entry per material in scene.materials: the object block it came from, so that
    // later stages (textures) can point at the scene file.
    std::vector<const ObjectDesc*> material_sources;
    std::vector<Diagnostic> diagnostics;
    std::size_t steps = 0;   // subgraph expansions and trans blocks walked (what the time was spent on)
    bool cancelled = false;  // FlattenLimits::cancel was set: no error, an incomplete scene
    bool ok() const { return !has_errors(diagnostics) && !cancelled; }
};

// What one object costs at the peak of a load: 60 bytes of Instance, about 25 of 4-wide BVH
// nodes and, where the CPU has AVX2, about 16 more of their 8-wide copy (about 50 where the scene
// has meshes: its top level is 8-wide only, accel/bvh_node.h) and the build's temporary arrays
// (bench/RESULTS.md: 1M instances, 160 MB peak RSS of a whole CLI run; 4.9 GB measured for 48M,
// 102 bytes each, before the 8-wide copy). Rounded up: an estimate must not be low.
constexpr std::size_t kBytesPerInstance = 128;
// And each step of the walk (a trans block or a subgraph use) may add one 8-byte provenance link,
// the pixel inspector's chain of lines (flatten/provenance.h).
constexpr std::size_t kBytesPerStep = 8;

struct FlattenLimits {
    // A few nested subgraphs can multiply into billions of objects: refused, with an error,
    // instead of running out of memory.
    std::size_t max_instances = 50'000'000;
    // The walk itself is bounded too: subgraphs that draw nothing are never entered, and what is
    // left (trans blocks and references leading to objects) may not take more steps than this.
    std::size_t max_steps = 200'000'000;
    // Memory: the objects at kBytesPerInstance and the steps at kBytesPerStep may not need more.
    std::size_t max_bytes = std::size_t(-1);
    // Set by another thread (or a signal handler) to give up; checked every few thousand steps.
    const std::atomic<bool>* cancel = nullptr;
};

FlattenResult flatten(const SceneDescription& desc, const FlattenLimits& limits = {});

// An instance of the unit shape `kind` placed by `object_to_world` (affine, invertible): keeps
// the three rows of its inverse that intersection needs.
Instance make_instance(const glm::dmat4& object_to_world, ShapeKind kind, std::uint32_t material);
inline Instance make_instance(const glm::mat4& object_to_world, ShapeKind kind, std::uint32_t material) {
    return make_instance(glm::dmat4(object_to_world), kind, material);
}

// The camera basis of spec §5 for an image of the given aspect ratio (width / height).
Camera make_camera(const CameraDesc& desc);

}  // namespace whitted
