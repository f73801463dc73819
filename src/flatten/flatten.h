#pragma once
// SceneDescription (a graph of mastersubgraphs) → FlatScene (one Instance per drawn object).
#include <cstddef>
#include <vector>

#include "flatten/flat_scene.h"
#include "parse/diagnostic.h"
#include "scene/scene_description.h"

namespace whitted {

struct FlattenResult {
    FlatScene scene;
    // One entry per material in scene.materials: the object block it came from, so that
    // later stages (textures) can point at the scene file.
    std::vector<const ObjectDesc*> material_sources;
    std::vector<Diagnostic> diagnostics;
    bool ok() const { return !has_errors(diagnostics); }
};

// Refuses scenes whose instancing would expand to more than `max_instances` objects
// (a few nested subgraphs can multiply into billions), with an error instead of running
// out of memory.
FlattenResult flatten(const SceneDescription& desc, std::size_t max_instances = 50'000'000);

// An instance of the unit shape `kind` placed by `object_to_world` (affine, invertible): keeps
// the three rows of its inverse that intersection needs.
Instance make_instance(const glm::dmat4& object_to_world, ShapeKind kind, std::uint32_t material);
inline Instance make_instance(const glm::mat4& object_to_world, ShapeKind kind, std::uint32_t material) {
    return make_instance(glm::dmat4(object_to_world), kind, material);
}

// The camera basis of spec §5 for an image of the given aspect ratio (width / height).
Camera make_camera(const CameraDesc& desc);

}  // namespace whitted
