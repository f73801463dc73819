#include "flatten/flatten.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <unordered_map>

#include "base/read_file.h"
#include "base/transforms.h"

namespace whitted {
namespace {

// World coordinates beyond this are refused: the acceleration structure adds and scales
// bounds, and offsets secondary rays relative to the hit point, which float cannot do near 1e38.
constexpr double kMaxWorldCoordinate = 1e30;

// Why float arithmetic cannot carry the composed object→world matrix, or "" when it can. Each
// trans block was checked alone by the parser; a chain of them can still overflow (ten nested
// `scale 1e5`), collapse (ten nested `scale 1e-5`) or carry an object out of range.
std::string unusable_transform(const glm::dmat4& world) {
    double reach = 0;  // how far the object's bounding cube extends from its centre, per axis
    for (int r = 0; r < 3; ++r) {
        const double half = 0.5 * (std::abs(world[0][r]) + std::abs(world[1][r]) + std::abs(world[2][r]));
        reach = std::max(reach, std::abs(world[3][r]) + half);
    }
    if (!(reach <= kMaxWorldCoordinate))
        return "the transforms down to this object, composed, put it more than 1e30 from the origin, beyond what "
               "float arithmetic can trace: scale or move the scene toward the origin";
    if (is_singular(glm::mat4(world)))
        return "the transforms down to this object, composed, are singular or too close to it for float (scales "
               "multiplied down to nothing, or axes squeezed together): scale the scene up, or undo the squeeze";
    return "";
}

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
    out.gloss = m.gloss;
    if (m.blend) out.blend = *m.blend;
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
    out.radius = l.radius;
    out.cos_half_angle = std::cos(glm::radians(l.angle_deg) * 0.5f);
    out.spot_outer_deg = l.aperture_deg;
    out.spot_inner_deg = l.aperture_deg - l.penumbra_deg;
    return out;
}

// What expanding each subgraph costs, saturating instead of overflowing: the instances it draws,
// and the steps of the walk (the subgraph itself, each of its trans blocks, and the steps of
// every referenced subgraph that draws something; one that draws nothing is never entered).
class ExpansionCounter {
public:
    ExpansionCounter(const SceneDescription& d, const SubgraphIndex& index)
        : desc_(d), index_(index), instances_(d.subgraphs.size(), kUnknown), steps_(d.subgraphs.size(), 0) {}

    // Children before parents, with an explicit stack: a chain of subgraphs may be 100,000 long.
    // The parser guarantees there are no cycles.
    void count(int root) {
        std::vector<std::pair<int, bool>> stack{{root, false}};  // subgraph, children pushed
        while (!stack.empty()) {
            auto [s, expanded] = stack.back();
            if (instances_[s] != kUnknown) {
                stack.pop_back();
                continue;
            }
            if (!expanded) {
                stack.back().second = true;
                for_each_child(s, [&](int child) {
                    if (instances_[child] == kUnknown) stack.push_back({child, false});
                });
                continue;
            }
            stack.pop_back();
            std::size_t n = 0, steps = add(1, desc_.subgraphs[s].children.size());
            for (const TransDesc& t : desc_.subgraphs[s].children) n = add(n, t.objects.size());
            for_each_child(s, [&](int child) {
                n = add(n, instances_[child]);
                if (instances_[child] > 0) steps = add(steps, steps_[child]);
            });
            instances_[s] = n;
            steps_[s] = steps;
        }
    }
    std::size_t instances(int s) const { return instances_[s]; }
    std::size_t steps(int s) const { return steps_[s]; }

private:
    template <class F>
    void for_each_child(int s, F&& f) const {
        for (const TransDesc& t : desc_.subgraphs[s].children)
            for (const SubgraphRef& ref : t.subgraphs)
                if (int child = find_subgraph(index_, ref.name); child >= 0) f(child);
    }
    static constexpr std::size_t kUnknown = std::numeric_limits<std::size_t>::max();
    static std::size_t add(std::size_t a, std::size_t b) { return a > kUnknown - 1 - b ? kUnknown - 1 : a + b; }
    const SceneDescription& desc_;
    const SubgraphIndex& index_;
    std::vector<std::size_t> instances_, steps_;
};

}  // namespace

Instance make_instance(const glm::dmat4& object_to_world, ShapeKind kind, std::uint32_t material) {
    // Invert in double: deep hierarchies of small scales lose precision fast in float.
    glm::dmat4 inv = glm::inverse(object_to_world);
    Instance inst{};
    for (int r = 0; r < 3; ++r)
        inst.world_to_object[r] = glm::vec4(float(inv[0][r]), float(inv[1][r]), float(inv[2][r]), float(inv[3][r]));
    inst.kind = kind;
    inst.material = material;
    float largest = 0.0f;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(inst.world_to_object[r][c]));
    inst.rescale = largest < 0x1p-20f || largest > 0x1p20f;
    return inst;
}

namespace {

// v / |v|: in float as always, in double where float's |v|² overflows or underflows (a camera 1e20
// from what it looks at), so that the camera of every scene that worked before is the same bits.
glm::vec3 unit(const glm::vec3& v) {
    const glm::vec3 u = glm::normalize(v);
    const float n = glm::dot(u, u);  // 0 or NaN where |v|² overflowed or underflowed
    return n > 0.5f && n < 2.0f ? u : glm::vec3(glm::normalize(glm::dvec3(v)));
}

}  // namespace

Camera make_camera(const CameraDesc& desc) {
    Camera cam;
    cam.eye = desc.eye;
    cam.forward = unit(desc.view_direction());
    cam.right = unit(glm::cross(cam.forward, desc.up));
    cam.up = glm::cross(cam.right, cam.forward);
    cam.tan_half_fov = std::tan(glm::radians(desc.angle_deg) * 0.5f);
    cam.lens_radius = 0.5f * desc.aperture;
    // The parser made sure a lens has something to focus on (§9.1).
    float focus = desc.use_focus ? glm::length(desc.focus - desc.eye) : 1.0f;
    if (!std::isfinite(focus)) focus = float(glm::length(glm::dvec3(desc.focus) - glm::dvec3(desc.eye)));
    cam.focal_distance = desc.focal_distance > 0.0f ? desc.focal_distance : focus;
    return cam;
}

FlattenResult flatten(const SceneDescription& desc, const FlattenLimits& limits) {
    FlattenResult result;
    SceneData& scene = result.scene;
    scene.background = desc.background;
    scene.ambient_intensity = desc.ambient_intensity;
    scene.lighting = desc.lighting;
    scene.camera = make_camera(desc.camera);
    // The camera within the objects' range: beyond, its rays' arithmetic overflows (a camera at
    // 3e38 saw nothing, silently).
    const CameraDesc& c = desc.camera;
    for (const auto& [what, where] : {std::pair{"eye", c.eye}, std::pair{"focus", c.use_focus ? c.focus : c.eye}})
        if (!(std::max({std::abs(where.x), std::abs(where.y), std::abs(where.z)}) <= kMaxWorldCoordinate)) {
            result.diagnostics.push_back(
                {Severity::Error, c.loc,
                 std::string("the camera's ") + what + " is more than 1e30 from the origin, beyond what float "
                 "arithmetic can trace: scale or move the scene toward the origin"});
            return result;
        }
    Provenance& prov = scene.provenance;
    for (const LightDesc& l : desc.lights) {
        scene.lights.push_back(to_light(l));
        prov.add_light(l.loc);
    }
    if (desc.root < 0) {
        Diagnostic d;
        d.loc.file = desc.path;
        d.message = "no mastersubgraph named 'root'";
        result.diagnostics.push_back(d);
        return result;
    }

    const SubgraphIndex index = index_subgraphs(desc);
    ExpansionCounter counter(desc, index);
    counter.count(desc.root);
    const std::size_t total = counter.instances(desc.root);
    if (total > limits.max_instances) {
        result.diagnostics.push_back(
            {Severity::Error, desc.subgraphs[desc.root].loc,
             "the scene expands to " + std::to_string(total) + " objects through subgraph instancing, more than the limit of " +
                 std::to_string(limits.max_instances)});
        return result;
    }
    // Saturating: a refused count must not wrap into an accepted estimate.
    const std::size_t steps = counter.steps(desc.root), max = std::size_t(-1);
    const std::size_t need = total > max / kBytesPerInstance || steps > max / kBytesPerStep / 2
                                 ? max
                                 : total * kBytesPerInstance + steps * kBytesPerStep;
    if (need > limits.max_bytes) {
        result.diagnostics.push_back(
            {Severity::Error, desc.subgraphs[desc.root].loc,
             "the scene needs about " + describe_bytes(need) + " of memory (" + std::to_string(total) +
                 " objects through subgraph instancing, about " + std::to_string(kBytesPerInstance) +
                 " bytes each with the BVH, and " + std::to_string(steps) + " steps of expanding them, " +
                 std::to_string(kBytesPerStep) + " bytes each), more than the limit of " +
                 describe_bytes(limits.max_bytes) + " (--max-memory)"});
        return result;
    }
    if (counter.steps(desc.root) > limits.max_steps) {
        result.diagnostics.push_back(
            {Severity::Error, desc.subgraphs[desc.root].loc,
             "expanding the scene's subgraph instancing takes " + std::to_string(counter.steps(desc.root)) +
                 " steps (trans blocks and subgraph references walked), more than the limit of " +
                 std::to_string(limits.max_steps) + ": deep chains of subgraphs referenced many times"});
        return result;
    }
    scene.instances.reserve(total);
    prov.reserve(counter.steps(desc.root), total);  // a link per step at most

    // One material per object block, however many times instancing draws it.
    std::unordered_map<const ObjectDesc*, std::uint32_t> material_of;
    auto material_index = [&](const ObjectDesc& o) {
        auto [it, inserted] = material_of.try_emplace(&o, std::uint32_t(scene.materials.size()));
        if (inserted) {
            scene.materials.push_back(to_material(o.material));
            result.material_sources.push_back(&o);
            prov.add_material(o.loc, o.material.texture ? o.material.texture->file : std::string());
        }
        return it->second;
    };

    // Depth-first walk with an explicit stack: a long chain of subgraphs must not overflow
    // the call stack. world = M(root's trans) · … · M(leaf trans) (spec §3).
    // Composed in double, so that long chains lose no precision before the single rounding.
    // Each frame also carries its provenance link (the subgraph's `mastersubgraph` line, below
    // the `subgraph` line that used it), the parent of its trans blocks' links.
    struct Frame {
        int subgraph;
        glm::dmat4 parent;
        std::uint32_t link;
        std::int64_t motion = -1;  // a moving chain above: its index in scene.motions
    };
    // The file's lines a chain can pass through, once each: every mastersubgraph first (a
    // `subgraph` line's site names its target's), then per trans block its own and its references'.
    std::vector<std::uint32_t> subgraph_site(desc.subgraphs.size()), first_trans(desc.subgraphs.size() + 1);
    std::vector<std::uint32_t> trans_site;
    std::vector<int> target;  // per site: the subgraph a `subgraph` line names (-1: none)
    // A CSCI 1230 file's subgraphs are its templates, its trans blocks its groups (§9.5).
    const bool json = desc.dialect == Dialect::Cs1230;
    for (std::size_t s = 0; s < desc.subgraphs.size(); ++s) {
        const SubgraphDesc& sg = desc.subgraphs[s];
        subgraph_site[s] = sg.implicit ? prov.add_site(LinkKind::ImplicitRoot, "", sg.loc)
                           : json      ? prov.add_site(int(s) == desc.root ? LinkKind::JsonRoot : LinkKind::JsonTemplate,
                                                       sg.name, sg.loc)
                                       : prov.add_site(LinkKind::Mastersubgraph, sg.name, sg.loc);
    }
    for (std::size_t s = 0; s < desc.subgraphs.size(); ++s) {
        first_trans[s] = std::uint32_t(trans_site.size());
        for (const TransDesc& t : desc.subgraphs[s].children) {
            trans_site.push_back(prov.add_site(json ? LinkKind::JsonGroup : LinkKind::Trans, "", t.loc));
            for (const SubgraphRef& ref : t.subgraphs) {  // sites trans_site + 1, + 2, …
                const int child = find_subgraph(index, ref.name);
                const std::uint32_t id = prov.add_site(json ? LinkKind::JsonTemplateUse : LinkKind::Subgraph, ref.name,
                                                       ref.loc, child >= 0 ? subgraph_site[child] : Provenance::kNone);
                target.resize(id + 1, -1);
                target[id] = child;
            }
        }
    }
    // The cancel flag is looked at every few thousand objects and steps, wherever they are: one
    // subgraph may hold a million objects, or a million subgraphs one each.
    std::size_t work = 0, next_look = 0;
    auto stop = [&] {
        if (work < next_look) return false;
        next_look = work + 4096;
        return result.cancelled = limits.cancel && limits.cancel->load(std::memory_order_relaxed);
    };
    std::vector<Frame> stack{{desc.root, glm::dmat4(1.0), prov.add_link(Provenance::kNone, subgraph_site[desc.root])}};
    while (!stack.empty()) {
        Frame f = stack.back();
        stack.pop_back();
        result.steps += 1 + desc.subgraphs[f.subgraph].children.size();
        work += 1 + desc.subgraphs[f.subgraph].children.size();
        if (stop()) return result;
        const std::vector<TransDesc>& children = desc.subgraphs[f.subgraph].children;
        for (std::size_t i = 0; i < children.size(); ++i) {
            const TransDesc& t = children[i];
            const glm::dmat4 world = f.parent * glm::dmat4(t.matrix);
            // The chain as a function of time, when it moves: the parent's, then this block's.
            std::int64_t motion = -1;
            if (f.motion >= 0 || !t.motion.empty()) {
                Motion chain;
                if (f.motion >= 0) chain = scene.motions[std::size_t(f.motion)];
                else chain.then_matrix(f.parent);
                if (t.motion.empty()) chain.then_matrix(glm::dmat4(t.matrix));
                else chain.then(t.motion);
                motion = std::int64_t(scene.motions.size());
                scene.motions.push_back(std::move(chain));
            }
            if (!t.objects.empty()) {
                if (std::string why = unusable_transform(world); !why.empty()) {
                    result.diagnostics.push_back({Severity::Error, t.objects.front().loc, why});
                    return result;
                }
            }
            // Linked only when something below it is drawn.
            const std::uint32_t site = trans_site[first_trans[f.subgraph] + i];
            std::uint32_t trans_link = Provenance::kNone;
            const auto link = [&] {
                if (trans_link == Provenance::kNone) trans_link = prov.add_link(f.link, site);
                return trans_link;
            };
            for (const ObjectDesc& o : t.objects) {
                if (motion >= 0)
                    scene.moving.push_back({std::uint32_t(scene.instances.size()), std::uint32_t(motion)});
                scene.instances.push_back(make_instance(world, o.kind, material_index(o)));
                prov.add_instance(link());
                if (++work >= next_look && stop()) return result;
            }
            for (std::uint32_t r = 0; r < t.subgraphs.size(); ++r) {
                // A subgraph that draws nothing is not entered: 41 levels of doubling over an
                // empty one would otherwise be 2^41 steps for no object at all.
                const std::uint32_t ref_site = site + 1 + r;
                if (int child = target[ref_site]; child >= 0 && counter.instances(child) > 0)
                    stack.push_back({child, world, prov.add_link(link(), ref_site), motion});
            }
        }
    }
    return result;
}

}  // namespace whitted
