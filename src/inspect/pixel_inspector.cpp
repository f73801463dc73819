#include "inspect/pixel_inspector.h"

#include <algorithm>
#include <cmath>

#include "film/film.h"
#include "integrator/cs1230_integrator.h"
#include "integrator/whitted_integrator.h"
#include "render/renderer.h"
#include "render/tile_renderer.h"

namespace whitted {
namespace {

// Shadow rays are followed through at most this many glass surfaces before the list stops.
constexpr int kMaxBlockers = 16;

HitInfo describe_hit(const Scene& scene, const ShadeNode& node) {
    HitInfo h;
    h.object = describe_object(scene, node.hit.instance);
    h.t = node.hit.t * glm::length(node.ray.direction);
    h.point = node.surface.point;
    h.normal = node.surface.normal;
    h.uv = node.surface.uv;
    h.outside = node.outside;
    return h;
}

// What lies between the shaded point and the light, nearest first, up to the first opaque thing.
std::vector<Blocker> blockers_toward(const Scene& scene, const ShadeNode& node, const LightTerm& term) {
    std::vector<Blocker> out;
    glm::vec3 start = node.surface.point + surface_offset(node.surface.point) * node.facing_normal;
    const glm::vec3 dir = term.sample.to_light;
    float reach = std::isinf(term.sample.distance) ? Scene::kInfinity : glm::length(term.sample.position - start);
    float travelled = 0;
    for (int i = 0; i < kMaxBlockers && reach > 0; ++i) {
        Hit h;
        if (!scene.intersect(Ray{start, dir}, h, reach)) break;
        Blocker b;
        b.object = describe_object(scene, h.instance);
        b.t = travelled + h.t;
        b.transparent = scene.material(h).is_transparent();
        out.push_back(b);
        if (!b.transparent) break;
        const glm::vec3 p = start + h.t * dir;
        const float step = h.t + surface_offset(p);
        start = start + step * dir;
        travelled += step;
        reach -= step;
    }
    return out;
}

SecondaryInfo describe_secondary(const Scene& scene, const ShadingRecorder& rec, const SecondaryRecord& r) {
    SecondaryInfo info;
    info.record = r;
    if (r.node >= 0) info.next = describe_hit(scene, rec.nodes[std::size_t(r.node)]);
    return info;
}

// The detail sample's ray tree (ray_tree.h) from its shading record: the camera ray, then below
// each hit its shadow rays (toward the lights it faces) and the reflected and refracted rays that
// were traced, depth first.
class TreeBuilder {
public:
    TreeBuilder(const Scene& scene, const ShadingRecorder& rec, RayTree& tree) : scene_(scene), rec_(rec), tree_(tree) {}

    void build(const Ray& camera_ray) {
        // A far point for a ray that leaves the scene: twice as far from the camera as anything recorded.
        for (const ShadeNode& n : rec_.nodes) reach_ = std::max(reach_, glm::length(n.surface.point - camera_ray.origin));
        for (const Light& l : scene_.data.lights)
            if (l.type != LightType::Directional) reach_ = std::max(reach_, glm::length(l.position - camera_ray.origin));
        reach_ *= 2.0f;
        RaySegment cam;
        cam.kind = RayKind::Camera;
        cam.from = camera_ray.origin;
        if (rec_.nodes.empty()) {
            cam.escaped = true;
            cam.to = camera_ray.origin + reach_ * glm::normalize(camera_ray.direction);
            tree_.segments.push_back(cam);
            return;
        }
        end_at(cam, 0);
        tree_.segments.push_back(cam);
        below(0, 0);
    }

private:
    void end_at(RaySegment& s, int node) {
        const ShadeNode& n = rec_.nodes[std::size_t(node)];
        s.to = n.surface.point;
        s.hit = true;
        const ObjectInfo o = describe_object(scene_, n.hit.instance);
        s.shape = o.kind;
        s.object = o.loc;
    }

    void below(int node, int segment) {
        const ShadeNode& n = rec_.nodes[std::size_t(node)];
        for (const LightTerm& t : n.lights) {
            if (!t.faces) continue;  // no shadow ray was traced
            RaySegment s;
            s.kind = RayKind::Shadow;
            s.depth = n.depth;
            s.parent = segment;
            s.from = n.surface.point;
            s.light = t.light;
            const bool far = std::isinf(t.sample.distance);
            s.to = far ? n.surface.point + reach_ * t.sample.to_light : t.sample.position;
            s.escaped = far;
            if (t.shadow == glm::vec3(0.0f)) {
                s.shadow = ShadowState::Blocked;
                // Up to the first opaque thing on the way (what stops the light).
                const std::vector<Blocker> blockers = blockers_toward(scene_, n, t);
                if (!blockers.empty() && !blockers.back().transparent) {
                    const glm::vec3 start = n.surface.point + surface_offset(n.surface.point) * n.facing_normal;
                    s.to = start + blockers.back().t * t.sample.to_light;
                    s.hit = true;
                    s.escaped = false;
                    s.shape = blockers.back().object.kind;
                    s.object = blockers.back().object.loc;
                }
            } else if (t.shadow != glm::vec3(1.0f)) {
                s.shadow = ShadowState::Tinted;
                s.tint = t.shadow;
            }
            tree_.segments.push_back(s);
        }
        for (const SecondaryRecord* r : {&n.reflect, &n.refract}) {
            if (r->outcome != SecondaryRecord::Outcome::Traced) continue;
            RaySegment s;
            const bool reflected = r == &n.reflect;
            s.kind = reflected ? RayKind::Reflected : RayKind::Refracted;
            s.depth = n.depth + 1;
            s.parent = segment;
            s.from = r->ray.origin;
            s.total_internal_reflection = reflected && n.total_internal_reflection;
            s.inside = reflected ? !n.outside : n.outside;  // a refracted ray crosses the surface
            if (r->node < 0) {
                s.escaped = true;
                s.to = r->ray.origin + reach_ * glm::normalize(r->ray.direction);
                tree_.segments.push_back(s);
                continue;
            }
            end_at(s, r->node);
            tree_.segments.push_back(s);
            below(r->node, int(tree_.segments.size()) - 1);
        }
    }

    const Scene& scene_;
    const ShadingRecorder& rec_;
    RayTree& tree_;
    float reach_ = 1.0f;
};

glm::vec3 clamped(const glm::vec3& c) { return {clamp01(c.x), clamp01(c.y), clamp01(c.z)}; }

// The pixel as the renderer renders it: a one-pixel region of the same job (an adaptive pixel
// still compares its centre with its neighbours': the renderer looks around its region).
FilmPixel render_pixel(const Integrator& integrator, RenderJob job, int x, int y, const std::atomic<bool>* cancel) {
    job.region = PixelRegion{x, y, x + 1, y + 1};
    job.sample_begin = 0;
    job.sample_end = -1;
    job.threads = 1;
    job.cancel = cancel;
    job.on_tile = nullptr;
    Film film(job.width, job.height, *job.region);
    render(integrator, job, film);
    return film.at(x, y);
}

void count_seen(const Scene& scene, std::vector<SeenCount>& seen, const ShadingRecorder& rec) {
    const bool background = rec.nodes.empty();
    const std::uint32_t instance = background ? 0 : rec.nodes[0].hit.instance;
    for (SeenCount& s : seen)
        if (s.background == background && (background || s.object.instance == instance)) {
            ++s.samples;
            return;
        }
    seen.push_back({background, background ? ObjectInfo{} : describe_object(scene, instance), 1});
}

// Sample i's share of the parts (the camera ray's hit: its terms; a miss: the background).
ColourParts parts_of(const ShadingRecorder& rec) {
    ColourParts p;
    if (rec.nodes.empty()) {
        p.background = rec.background;
        return p;
    }
    const ShadeNode& n = rec.nodes[0];
    p.emit = n.emit;
    p.ambient = n.ambient;
    for (const LightTerm& t : n.lights) {
        p.diffuse += t.diffuse;
        p.specular += t.specular;
    }
    p.reflect = n.reflect.contribution;  // under total internal reflection it carries the transparent weight
    p.transparent = n.refract.contribution;
    return p;
}

void add_scaled(ColourParts& to, const ColourParts& p, float s) {
    to.ambient += s * p.ambient;
    to.diffuse += s * p.diffuse;
    to.specular += s * p.specular;
    to.reflect += s * p.reflect;
    to.transparent += s * p.transparent;
    to.emit += s * p.emit;
    to.background += s * p.background;
    to.clamp += s * p.clamp;
}

}  // namespace

ObjectInfo describe_object(const Scene& scene, std::uint32_t instance) {
    ObjectInfo o;
    o.instance = instance;
    const Instance& inst = scene.data.instances[instance];
    o.kind = inst.kind;
    o.material = inst.material;
    o.loc = scene.data.provenance.material_object(inst.material);
    o.chain = scene.data.provenance.chain(instance);
    return o;
}

PixelReport inspect_pixel(const Scene& scene, const RenderJob& job, int x, int y, const std::atomic<bool>* cancel) {
    PixelReport r;
    r.x = x;
    r.y = y;
    r.width = job.width;
    r.height = job.height;
    r.mode = job.integrator.mode;
    r.max_depth = job.integrator.max_depth;
    r.sampling = job.sampling;
    r.background = scene.data.background;

    const Camera camera = job.camera_for(scene);
    const auto integrator = make_integrator(scene, camera, job.integrator);
    auto cancelled = [&] { return r.cancelled = cancel && cancel->load(std::memory_order_relaxed); };
    const FilmPixel pixel = render_pixel(*integrator, job, x, y, cancel);
    if (cancelled()) return r;
    r.value = pixel.value();
    r.bytes = {to_byte(r.value.x), to_byte(r.value.y), to_byte(r.value.z)};
    r.samples = int(pixel.weight);

    // The samples the film took: adaptive anti-aliasing leaves a pixel like its neighbours with
    // its centre alone (the renderer's first look, with a one-sample sampler).
    const Sampler all(job.sampling.aa, job.sampling.spp, job.sampling.seed);
    const bool centre_only = job.sampling.adaptive() && r.samples == 1;
    const Sampler sampler = centre_only ? Sampler() : all;
    const int n = sampler.samples_per_pixel();

    // The Whitted model's shading of each sample, recorded. In the other modes it still tells
    // what the camera ray hit, the lights and the mirror and glass rays, but not the colour.
    const WhittedIntegrator whitted(scene, camera, job.integrator.max_depth);
    // A CSCI 1230 scene is shaded by the course's model (§9.5), whose colour is also truncated to
    // bytes: what clamping and truncating took away is the difference to the sum of the parts.
    const Cs1230Integrator course(scene, camera, job.integrator.max_depth, job.integrator.cs1230_stage);
    const bool by_course = scene.data.lighting == LightingModel::Cs1230;
    r.decomposed = job.integrator.mode == RenderMode::Whitted;
    const bool clamps = integrator->clamps_samples();
    float best = Scene::kInfinity;
    ShadingRecorder detail;
    for (int i = 0; i < n; ++i) {
        if (cancelled()) return r;
        const SampleKey key{std::uint32_t(x), std::uint32_t(y), std::uint32_t(i)};
        const Ray ray = camera_sample_ray(camera, sampler, job.width, job.height, x, y, key.index,
                                          !scene.motion.empty());
        ShadingRecorder rec;
        RayCounts counts;
        const glm::vec3 c = by_course ? course.radiance(ray, key, sampler, counts, rec)
                                      : whitted.radiance(ray, key, sampler, counts, rec);
        ColourParts p = parts_of(rec);
        if (by_course) p.clamp = c - p.sum();
        else if (clamps) p.clamp = clamped(c) - c;  // what the film takes of the sample (§7)
        add_scaled(r.parts, p, 1.0f / float(n));
        count_seen(scene, r.seen, rec);
        const glm::vec2 at = sampler.centred() ? glm::vec2(0.5f) : sampler.pixel_offset(key);
        const float d = glm::length(at - glm::vec2(0.5f));
        if (d < best) {
            best = d;
            r.detail_sample = i;
            r.camera_ray = ray;
            detail = std::move(rec);
        }
    }
    if (!r.decomposed) {
        r.parts = ColourParts{};
        r.note = job.integrator.mode == RenderMode::Path
                     ? "path mode: the colour is the mean of the pixel's path-traced samples (Monte Carlo estimates "
                       "of radiance) and is not split into parts; the hit, lights and rays below are the Whitted "
                       "model's view of the same camera rays"
                     : std::string(render_mode_name(job.integrator.mode)) +
                           " mode: a debugging view, its colour is not lighting and is not split into parts";
    }

    r.ray_tree.camera = camera;
    r.ray_tree.width = job.width;
    r.ray_tree.height = job.height;
    TreeBuilder(scene, detail, r.ray_tree).build(r.camera_ray);

    if (detail.nodes.empty()) return r;  // the background
    const ShadeNode& node = detail.nodes[0];
    r.hit = describe_hit(scene, node);
    r.material = *node.surface.material;
    r.material_loc = r.hit->object.loc;
    r.texture_file = scene.data.provenance.material_texture(r.hit->object.material);
    r.diffuse_at_hit = node.surface.diffuse;
    r.ambient_at_hit = node.surface.ambient;
    for (const LightTerm& t : node.lights) {
        LightInfo li;
        li.term = t;
        li.type = scene.data.lights[t.light].type;
        li.loc = scene.data.provenance.light(t.light);
        const float m = std::max(t.shadow.x, std::max(t.shadow.y, t.shadow.z));
        const float lo = std::min(t.shadow.x, std::min(t.shadow.y, t.shadow.z));
        if (t.faces && (m <= 0.0f || lo < 1.0f)) li.blockers = blockers_toward(scene, node, t);
        r.lights.push_back(std::move(li));
    }
    r.total_internal_reflection = node.total_internal_reflection;
    r.depth_limit = node.depth_limit;
    r.reflected = describe_secondary(scene, detail, node.reflect);
    r.refracted = describe_secondary(scene, detail, node.refract);
    return r;
}

}  // namespace whitted
