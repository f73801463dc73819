#include "flatten/flatten.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace whitted {
namespace {

Material to_material(const MaterialDesc& m) {
    Material out;
    out.ambient = m.ambient;
    out.diffuse = m.diffuse;
    out.specular = m.specular;
    out.reflect = m.reflect;
    out.transparent = m.transparent;
    out.emit = m.emit;
    out.shine = m.shine;
    out.ior = m.ior;
    if (m.texture) {
        out.repeat_u = m.texture->repeat_u;
        out.repeat_v = m.texture->repeat_v;
    }
    return out;  // texture index is resolved by the texture stage
}

Light to_light(const LightDesc& l) {
    Light out;
    out.type = l.type;
    out.position = l.position;
    float len = glm::length(l.direction);
    out.direction = len > 0 ? l.direction / len : glm::vec3(0, -1, 0);
    out.color = l.color;
    out.falloff = l.falloff;
    out.cos_aperture = std::cos(glm::radians(l.aperture_deg));
    if (l.aperture_deg >= 180.0f) out.cos_aperture = -1.0f;
    out.exponent = l.exponent;
    return out;
}

// Number of instances each subgraph expands to, saturating instead of overflowing.
class InstanceCounter {
public:
    explicit InstanceCounter(const SceneDescription& d) : desc_(d), memo_(d.subgraphs.size(), kUnknown) {}

    std::size_t count(int s) {
        if (memo_[s] != kUnknown) return memo_[s];
        std::size_t n = 0;
        for (const TransDesc& t : desc_.subgraphs[s].children) {
            n = add(n, t.objects.size());
            for (const SubgraphRef& ref : t.subgraphs) {
                int child = desc_.find_subgraph(ref.name);
                if (child >= 0) n = add(n, count(child));  // the parser guarantees no cycles
            }
        }
        return memo_[s] = n;
    }

private:
    static constexpr std::size_t kUnknown = std::numeric_limits<std::size_t>::max();
    static std::size_t add(std::size_t a, std::size_t b) { return a > kUnknown - 1 - b ? kUnknown - 1 : a + b; }
    const SceneDescription& desc_;
    std::vector<std::size_t> memo_;
};

}  // namespace

Instance make_instance(const glm::mat4& object_to_world, ShapeKind kind, std::uint32_t material) {
    // Invert in double: deep hierarchies of small scales lose precision fast in float.
    glm::dmat4 inv = glm::inverse(glm::dmat4(object_to_world));
    Instance inst{};
    for (int r = 0; r < 3; ++r)
        inst.world_to_object[r] = glm::vec4(float(inv[0][r]), float(inv[1][r]), float(inv[2][r]), float(inv[3][r]));
    inst.kind = kind;
    inst.material = material;
    return inst;
}

Camera make_camera(const CameraDesc& desc) {
    Camera cam;
    cam.eye = desc.eye;
    cam.forward = glm::normalize(desc.view_direction());
    cam.right = glm::normalize(glm::cross(cam.forward, desc.up));
    cam.up = glm::cross(cam.right, cam.forward);
    cam.tan_half_fov = std::tan(glm::radians(desc.angle_deg) * 0.5f);
    return cam;
}

FlattenResult flatten(const SceneDescription& desc, std::size_t max_instances) {
    FlattenResult result;
    FlatScene& scene = result.scene;
    scene.background = desc.background;
    scene.ambient_intensity = desc.ambient_intensity;
    scene.camera = make_camera(desc.camera);
    for (const LightDesc& l : desc.lights) scene.lights.push_back(to_light(l));
    if (desc.root < 0) {
        Diagnostic d;
        d.loc.file = desc.path;
        d.message = "no mastersubgraph named 'root'";
        result.diagnostics.push_back(d);
        return result;
    }

    InstanceCounter counter(desc);
    std::size_t total = counter.count(desc.root);
    if (total > max_instances) {
        result.diagnostics.push_back(
            {Severity::Error, desc.subgraphs[desc.root].loc,
             "the scene expands to " + std::to_string(total) + " objects through subgraph instancing, more than the limit of " +
                 std::to_string(max_instances)});
        return result;
    }
    scene.instances.reserve(total);

    // One material per object block, however many times instancing draws it.
    std::unordered_map<const ObjectDesc*, std::uint32_t> material_of;
    auto material_index = [&](const ObjectDesc& o) {
        auto [it, inserted] = material_of.try_emplace(&o, std::uint32_t(scene.materials.size()));
        if (inserted) {
            scene.materials.push_back(to_material(o.material));
            result.material_sources.push_back(&o);
        }
        return it->second;
    };

    // Depth-first walk with an explicit stack: a long chain of subgraphs must not overflow
    // the call stack. world = M(root's trans) · … · M(leaf trans) (spec §3).
    struct Frame {
        int subgraph;
        glm::mat4 parent;
    };
    std::vector<Frame> stack{{desc.root, glm::mat4(1.0f)}};
    while (!stack.empty()) {
        Frame f = stack.back();
        stack.pop_back();
        for (const TransDesc& t : desc.subgraphs[f.subgraph].children) {
            glm::mat4 world = f.parent * t.matrix;
            for (const ObjectDesc& o : t.objects) scene.instances.push_back(make_instance(world, o.kind, material_index(o)));
            for (const SubgraphRef& ref : t.subgraphs) {
                int child = desc.find_subgraph(ref.name);
                if (child >= 0) stack.push_back({child, world});
            }
        }
    }
    return result;
}

}  // namespace whitted
