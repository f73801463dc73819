#pragma once
// The ray tree of one sample of a pixel: its camera ray, and at each hit the shadow rays toward the
// lights and the reflected and refracted rays, down to where the Whitted shading stopped, as
// segments in world space. Recorded by the renderer's own shading (integrator/shading_record.h,
// built by inspect_pixel). For drawing over the image (projected with the render's camera), for
// reading (one entry per segment), and for export: OBJ polylines (Blender opens them) and JSON.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "base/diagnostic.h"
#include "camera/camera.h"
#include "data/shape_kind.h"
#include "integrator/ray_counts.h"  // RayKind

namespace whitted {

const char* ray_kind_name(RayKind kind);  // "camera", "reflected", "refracted", "shadow"

// What a shadow ray meets on its way to the light.
enum class ShadowState { Lit, Blocked, Tinted };
const char* shadow_state_name(ShadowState state);  // "lit", "blocked", "tinted"

struct RaySegment {
    RayKind kind = RayKind::Camera;
    // The bounce it belongs to: the camera ray 0; the rays leaving a hit of depth d: d + 1 for the
    // reflected and refracted ones, d for its shadow rays (they belong to the hit's shading).
    int depth = 0;
    int parent = -1;  // the segment at whose end this one starts (-1: none, the camera ray)
    glm::vec3 from{0.0f}, to{0.0f};  // world space
    // How it ends: on a surface (a shadow ray: the opaque thing blocking it), or leaving the scene
    // (`to` is then a point far along it), or (a shadow ray that is not blocked) at the light.
    bool hit = false, escaped = false;
    ShapeKind shape = ShapeKind::Cube;  // what it hit, when hit
    SourceLoc object;                   // that object's `object` keyword
    bool total_internal_reflection = false;  // a reflected ray carrying the refracted share: TIR at `from`
    bool inside = false;  // it travels inside a transparent object (it left a hit from inside)
    // Shadow rays: toward light `light` (0-based, the order of the file), and what reaches the point.
    std::size_t light = 0;
    ShadowState shadow = ShadowState::Lit;
    glm::vec3 tint{1.0f};  // Tinted: what the glass lets through
};

struct RayTree {
    Camera camera;  // the render's camera and image size: where the tree lands in the image
    int width = 0, height = 0;
    std::vector<RaySegment> segments;  // each after its parent; the camera ray first (if any)
    int deepest() const;  // the largest depth of a segment (0 without any)
};

// Where world point p appears in the image of `camera` (width × height): pixel coordinates from the
// image's top-left corner, x right, y down, a pixel's centre at +0.5; the pinhole projection through
// the eye. None for a point not in front of the camera.
std::optional<glm::vec2> project_point(const Camera& camera, int width, int height, const glm::vec3& p);

// A segment projected into the image and cut to it (and to the part in front of the camera): its
// ends in pixel coordinates, as project_point gives them. None when no part of it shows.
struct ImageSegment {
    glm::vec2 a{0.0f}, b{0.0f};
};
std::optional<ImageSegment> project_segment(const Camera& camera, int width, int height, const glm::vec3& from,
                                            const glm::vec3& to);

// One line per segment: "  2 refracted  depth 2 from (x y z) to (x y z): hits sphere at FILE:L:C".
std::string ray_tree_text(const RayTree& tree, const std::string& base_dir);
// OBJ: a `v` per end and an `l` per segment, each segment an object named after its number, kind
// and depth ("o 2_refracted_depth2").
std::string ray_tree_obj(const RayTree& tree, const std::string& title);
// JSON: {"pixel":[x,y],"image":[w,h],"camera":{...},"segments":[{...}, ...]}.
std::string ray_tree_json(const RayTree& tree, int x, int y, const std::string& base_dir);

}  // namespace whitted
