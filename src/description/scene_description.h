#pragma once
// The scene as the file describes it: camera, lights, and the graph of mastersubgraphs.
// Produced by parse/, validated there (names resolve, no cycles, matrices invertible, ranges),
// consumed by flatten/. Plain data, no behaviour; its shape and light kinds are the
// render-ready data's (data/).
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "base/diagnostic.h"
#include "data/light_type.h"
#include "data/lighting_model.h"
#include "data/motion.h"
#include "data/shape_kind.h"

namespace whitted {

// Which family of files the scene was written in (scene-format.md §9.4, §9.5): the labs' own format
// (mastersubgraphs), the Brown/Tufts one (top-level trans blocks, `light [ number N`), or Brown
// CSCI 1230's JSON files (read by cs1230/, not by parse/).
enum class Dialect : unsigned char { Labs, BrownTufts, Cs1230 };
const char* dialect_name(Dialect dialect);

struct TextureRef {
    std::string file;  // as written in the scene
    float repeat_u = 1, repeat_v = 1;
    SourceLoc loc;  // of the `texture` keyword
    // Brown/Tufts files name textures by their authors' paths (`C:\Users\...\earth.bmp`,
    // `image/earth.bmp` beside an earth.ppm): when the usual look-up fails, trailing parts of the
    // path and other extensions are tried (§9.4). Windows paths get this in every file.
    bool loose_lookup = false;
    bool allow_gif = false;  // CSCI 1230 files: GIF is decoded too (§9.5; their course ships one)
};

struct MaterialDesc {
    glm::vec3 ambient{0.0f}, diffuse{1.0f}, specular{0.0f};
    glm::vec3 reflect{0.0f}, transparent{0.0f}, emit{0.0f};
    float shine = 1.0f;
    float ior = 1.0f;
    float gloss = 0.0f;  // §9.1: cos^gloss lobe for reflect/transparent rays; 0 = ideal directions
    std::optional<TextureRef> texture;
    // Brown/Tufts `blend b`: diffuse = (1 − b)·diffuse + b·texel instead of diffuse·texel.
    std::optional<float> blend;
};

struct CameraDesc {
    glm::vec3 eye{0, 0, 1};
    glm::vec3 look{0, 0, -1};  // direction, used unless `focus` came later
    glm::vec3 focus{0, 0, 0};  // point looked at
    bool use_focus = false;    // the later of look/focus wins
    glm::vec3 up{0, 1, 0};
    float angle_deg = 60;  // full vertical field of view
    float near_plane = 0.1f, far_plane = 1000.0f;  // kept, never clips rays
    float aperture = 0.0f;        // §9.1: thin-lens diameter; 0 = pinhole
    float focal_distance = 0.0f;  // §9.1: 0 = not given (then |focus - eye|)
    SourceLoc loc;  // of the last camera block (for messages)

    glm::vec3 view_direction() const { return use_focus ? focus - eye : look; }
};

struct LightDesc {
    LightType type = LightType::Point;
    glm::vec3 position{1, 1, 1};
    glm::vec3 direction{0, -1, 0};
    glm::vec3 color{0.5f, 0.5f, 0.5f};
    glm::vec3 falloff{1, 0, 0};  // `function c l q`
    float aperture_deg = 180;
    float exponent = 1;
    float radius = 0;     // §9.1: point/spot light as a disc of this radius
    float angle_deg = 0;  // §9.1: angular diameter of a directional light
    float penumbra_deg = 0;  // §9.5 (CSCI 1230 spot): the falloff band inside aperture_deg, the outer half-angle
    SourceLoc loc;
};

struct ObjectDesc {
    ShapeKind kind = ShapeKind::Cube;
    MaterialDesc material;
    SourceLoc loc;
    std::string mesh_file = {};  // kind == Mesh: the OBJ file as written (§9.3)
    SourceLoc mesh_loc = {};     // of its `file` keyword
};

struct SubgraphRef {
    std::string name;
    SourceLoc loc;
};

struct TransDesc {
    glm::mat4 matrix{1.0f};  // T1 · T2 · … · Tn in the order written
    // With `velocity` or `angularrate`: the same product as a function of time (matrix is it at
    // the load's time); empty for a block that does not move.
    Motion motion;
    std::vector<ObjectDesc> objects;
    std::vector<SubgraphRef> subgraphs;
    SourceLoc loc;
};

struct SubgraphDesc {
    std::string name;
    std::vector<TransDesc> children;
    SourceLoc loc;
    bool implicit = false;  // Brown/Tufts: the top-level trans blocks (§9.4); loc is the first one
};

struct SceneDescription {
    std::string path;  // the scene file (textures are looked up relative to it)
    glm::vec3 background{0.0f};
    glm::vec3 ambient_intensity{1.0f};  // global I_a; see scene-format.md §6 (decision)
    CameraDesc camera;
    std::vector<LightDesc> lights;  // blocks holding only `ambient` are not listed
    std::vector<SubgraphDesc> subgraphs;
    int root = -1;  // index of `root` in subgraphs
    Dialect dialect = Dialect::Labs;
    LightingModel lighting = LightingModel::Labs;  // how the scene is lit: §7, or CSCI 1230's §9.5
    // Whether a trans block says `velocity` or `angularrate` (§9.4): the scene differs with the time.
    bool moves = false;
    // The file that textures and meshes are looked up next to, when not `path` (§9.5: a CSCI 1230
    // file names them relative to the parent of its folder).
    std::string asset_anchor;
    const std::string& assets_from() const { return asset_anchor.empty() ? path : asset_anchor; }

    // Index of the mastersubgraph with that name, or -1 (a linear scan: see SubgraphIndex).
    int find_subgraph(const std::string& name) const;
};

// Name → index of every mastersubgraph, built once for code that looks many names up (a file may
// hold thousands of mastersubgraphs, each referenced many times). Its keys point into `scene`.
using SubgraphIndex = std::unordered_map<std::string_view, int>;
SubgraphIndex index_subgraphs(const SceneDescription& scene);
// The index of `name` in it, or -1.
int find_subgraph(const SubgraphIndex& index, std::string_view name);

}  // namespace whitted
