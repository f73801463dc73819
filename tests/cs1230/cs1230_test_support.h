#pragma once
// Helpers for the CSCI 1230 tests: small JSON scenes written in the test, loaded through the
// public API (load_scene_text), and single rays traced by the course's model with the shading
// recorded (the colour before truncation, each light's terms, the surface's u, v and texel).
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "integrator/cs1230_integrator.h"
#include "render/load_scene.h"

namespace whitted::test {

// A CSCI 1230 scene: the global coefficients, a camera at (0, 0, 5) looking at the origin (unless
// `camera` gives another cameraData body), and the given groups (a JSON array's contents).
inline std::string json_scene(const std::string& groups, float ka = 0.5f, float kd = 0.5f, float ks = 0.5f,
                              float kt = 0.0f, const std::string& camera = "", const std::string& templates = "") {
    std::string s = "{\n  \"name\": \"root\",\n  \"globalData\": {\"ambientCoeff\": " + std::to_string(ka) +
                    ", \"diffuseCoeff\": " + std::to_string(kd) + ", \"specularCoeff\": " + std::to_string(ks) +
                    ", \"transparentCoeff\": " + std::to_string(kt) + "},\n";
    s += "  \"cameraData\": {" +
         (camera.empty() ? std::string("\"position\": [0, 0, 5], \"up\": [0, 1, 0], \"heightAngle\": 45, "
                                       "\"focus\": [0, 0, 0]")
                         : camera) +
         "},\n";
    if (!templates.empty()) s += "  \"templateGroups\": [" + templates + "],\n";
    s += "  \"groups\": [" + groups + "]\n}\n";
    return s;
}

// A group holding one light or one primitive (JSON object bodies), with optional transforms
// ("\"translate\": [0, 0, 3], " …, each ending in a comma).
inline std::string light_group(const std::string& light, const std::string& transforms = "") {
    return "{" + transforms + "\"lights\": [{" + light + "}]}";
}
inline std::string primitive_group(const std::string& primitive, const std::string& transforms = "") {
    return "{" + transforms + "\"primitives\": [{" + primitive + "}]}";
}

// Loads the text as the file `path` (its textures are looked for in the parent of its folder).
inline LoadResult load_json(const std::string& text, const std::string& path = "/nonexistent/scenes/test.json",
                            cs1230::Stage stage = cs1230::Stage::Illuminate) {
    LoadOptions o;
    o.threads = 1;
    o.cs1230_stage = stage;
    return load_scene_text(text, path, o);
}

inline std::string diagnostics_text(const LoadResult& r) {
    std::string s;
    for (const Diagnostic& d : r.diagnostics) s += d.str() + "\n";
    return s;
}

// One ray traced by the course's model, recorded.
struct Traced {
    glm::vec3 written;  // what the renderer gets: clamped and truncated to 1/255 steps
    ShadingRecorder rec;
    const ShadeNode& hit() const { return rec.nodes.at(0); }
    glm::vec3 color() const { return rec.nodes.at(0).color; }  // clamped, before truncation
};

inline Traced trace(const Scene& scene, const Ray& ray, int max_depth = 4,
                    cs1230::Stage stage = cs1230::Stage::Illuminate) {
    Traced t;
    RayCounts counts;
    const Cs1230Integrator course(scene, scene.data.camera, max_depth, stage);
    t.written = course.radiance(Ray{ray.origin, glm::normalize(ray.direction)}, SampleKey{}, Sampler(), counts, t.rec);
    return t;
}

inline void expect_vec_near(const glm::vec3& got, const glm::vec3& want, float tol = 1e-5f) {
    EXPECT_NEAR(got.x, want.x, tol) << "x";
    EXPECT_NEAR(got.y, want.y, tol) << "y";
    EXPECT_NEAR(got.z, want.z, tol) << "z";
}

}  // namespace whitted::test
