#pragma once
// A Brown CSCI 1230 JSON scene file → the scene's description (scene-format.md §9.5), the way the
// course's stencil reader reads it (BrownCSCI1230/projects_ray_template, scenefilereader.cpp):
// the same keys, defaults and transform order, unknown keys refused. Every problem is reported
// at the key or value it is about, all of them in one run.
//
// How the file maps onto whitted's description: the file's top-level groups are the root
// subgraph and each template group a subgraph of its own; a group holding primitives becomes a
// trans block whose matrix is the product of the groups' T·R·S·Matrix from its scope (the root or
// the template) down to it; a group naming a template becomes a reference to that subgraph, under
// its parent's matrix. Lights are placed by walking the same graph (a template's lights once per
// use). The global coefficients are folded into each material (ambient = ka·Oa, diffuse = kd·Od,
// specular = ks·Os, reflect = ks·Or, transparent = kt·Ot), and the scene is marked to be lit by
// the course's model (integrator/cs1230_integrator.h). Textures and meshes are named relative to
// the parent of the file's folder.
#include <cstddef>
#include <string>
#include <string_view>

#include "parse/parser.h"

namespace whitted::cs1230 {

struct ReadOptions {
    // Lights after templates are expanded (a template used many times, inside others used many
    // times, multiplies its lights); every light is visited at every shaded point.
    std::size_t max_lights = 100'000;
    // An unknown key is skipped with a warning instead of being an error (--lenient).
    bool lenient = false;
};

ParseResult read_scene(std::string_view text, const std::string& path, const ReadOptions& options = {});

}  // namespace whitted::cs1230
