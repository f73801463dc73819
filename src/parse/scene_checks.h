#pragma once
// Checks that need the whole file: subgraph names resolve, no cycles, `root` exists, camera sane.
// Each returns the first problem found (in file order) as an error, or nothing.
#include <optional>

#include "base/diagnostic.h"
#include "description/scene_description.h"

namespace whitted {

// Every `subgraph NAME` names a mastersubgraph (anywhere in the file: forward references are fine).
std::optional<Diagnostic> check_subgraph_references(const SceneDescription& scene);

// No mastersubgraph instantiates itself, directly or not. The message names the cycle
// ("subgraph cycle: a -> b -> a") and points at the reference that closes it.
// Requires check_subgraph_references to have passed.
std::optional<Diagnostic> check_subgraph_cycles(const SceneDescription& scene);

// The view direction (look, or focus - eye with the final eye) and `up` are non-zero and not
// parallel. `up_loc` / `view_loc`: where `up` / the winning look-or-focus was written (line 0 if
// never), used to point at the culprit.
std::optional<Diagnostic> check_camera(const CameraDesc& camera, const SourceLoc& up_loc,
                                       const SourceLoc& view_loc);

}  // namespace whitted
