#include "integrator/path_integrator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string_view>
#include <tuple>

#include "accel/instance_geometry.h"
#include "integrator/bsdf.h"
#include "integrator/light_sample.h"
#include "integrator/surface.h"
#include "integrator/whitted_integrator.h"  // surface_offset
#include "sampler/warp.h"                   // kPi

namespace whitted {
namespace {

float max_component(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

float power_heuristic(float a, float b) {
    const float a2 = a * a, b2 = b * b;
    return a2 + b2 > 0.0f ? a2 / (a2 + b2) : 0.0f;
}

// A point just off the surface on the side `w` leaves toward.
glm::vec3 spawn(const glm::vec3& p, const glm::vec3& outward, const glm::vec3& w) {
    const float off = surface_offset(p);
    return p + (glm::dot(w, outward) > 0.0f ? off : -off) * outward;
}

}  // namespace

struct PathIntegrator::Vertex {
    Surface s;
    Bsdf bsdf;
    glm::vec3 wo;
    float time;  // the camera sample's shutter time, for the rays this vertex spawns
};

PathIntegrator::PathIntegrator(const Scene& scene, const Camera& camera, int max_bounces)
    : Integrator(scene, camera), max_bounces_(max_bounces), lights_(scene) {}

void PathIntegrator::radiance(const CameraBatch& batch, const Sampler& sampler, glm::vec3 (&out)[kPacketSize],
                              RayCounts& counts) const {
    Hit hits[kPacketSize];
    const unsigned found = timed_trace(counts, RayKind::Camera, std::popcount(batch.active),
                                       [&] { return scene_.intersect(batch.rays, batch.active, hits); });
    for (int l = 0; l < kPacketSize; ++l)
        if ((batch.active >> l) & 1)
            out[l] = radiance(batch.rays[l], batch.keys[l], sampler, counts, (found >> l) & 1 ? &hits[l] : nullptr, true);
}

// Light arriving at vertex v from one light chosen by power, times the BSDF and the cosine, divided
// by the densities (and weighted against BSDF sampling for area lights).
glm::vec3 PathIntegrator::next_event(const Vertex& v, int bounce, glm::vec2 choice, glm::vec2 u, const SampleKey& key,
                                     const Sampler& sampler, RayCounts& counts) const {
    if (lights_.empty() || !v.bsdf.has_non_delta()) return glm::vec3(0.0f);
    float prob;
    const PathLight& pick = lights_.choose(choice.x, prob);
    const glm::vec3 x = v.s.point;

    if (pick.instance >= 0) {
        const std::uint32_t light = std::uint32_t(pick.instance);
        // An emissive mesh draws its triangle from a dimension of its own (the unit shapes need two).
        const float u_triangle = scene_.data.instances[light].kind == ShapeKind::Mesh
                                     ? sampler.get2d(key, dimension::path(bounce, dimension::kPathLightTriangle)).x
                                     : 0.0f;
        const AreaLightSample ls = lights_.sample_area(light, x, u, u_triangle);
        glm::vec3 to = ls.point - x;
        const float d2 = glm::dot(to, to), d = std::sqrt(d2);
        if (!(d > 0.0f)) return glm::vec3(0.0f);
        to /= d;
        const float cos_light = std::abs(glm::dot(ls.normal, to));
        if (!(cos_light > 0.0f)) return glm::vec3(0.0f);
        const glm::vec3 f = v.bsdf.f(to);
        const float cos_x = std::abs(glm::dot(v.bsdf.normal(), to));
        if (max_component(f) <= 0.0f || !(cos_x > 0.0f)) return glm::vec3(0.0f);
        const float pdf_light = prob * ls.pdf_area * d2 / cos_light;  // per unit solid angle at x
        const glm::vec3 start = spawn(x, v.s.normal, to);
        ++counts.shadow;
        if (timed_trace(counts, RayKind::Shadow, 1,
                        [&] { return scene_.occluded(Ray{start, ls.point - start, v.time}, 1.0f - 1e-4f); }))
            return glm::vec3(0.0f);
        const float w = power_heuristic(pdf_light, v.bsdf.pdf(to));
        return scene_.material(std::uint32_t(pick.instance)).emit * f * (cos_x * w / pdf_light);
    }

    // A point, spot or directional light: its §6/§9.1 intensity, as the Whitted diffuse term
    // counts it (π · f · C · att · spot · cos θ), reached by this estimate alone.
    const Light& light = scene_.data.lights[std::size_t(pick.light)];
    const LightSample ls = sampler.centred() || !has_extent(light) ? sample_light(light, x) : sample_light(light, x, u);
    const float cos_x = std::abs(glm::dot(v.bsdf.normal(), ls.to_light));
    if (max_component(ls.intensity) <= 0.0f || !(cos_x > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 f = v.bsdf.f(ls.to_light);
    if (max_component(f) <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 start = spawn(x, v.s.normal, ls.to_light);
    ++counts.shadow;
    const bool blocked = timed_trace(counts, RayKind::Shadow, 1, [&] {
        return std::isinf(ls.distance) ? scene_.occluded(Ray{start, ls.to_light, v.time}, Scene::kInfinity)
                                       : scene_.occluded(Ray{start, ls.position - start, v.time}, 1.0f - 1e-4f);
    });
    if (blocked) return glm::vec3(0.0f);
    return kPi * f * ls.intensity * (cos_x / prob);
}

glm::vec3 PathIntegrator::radiance(const Ray& camera_ray, const SampleKey& key, const Sampler& sampler,
                                   RayCounts& counts, const Hit* first, bool first_known, glm::vec3* direct) const {
    ++counts.camera;
    glm::vec3 radiance(0.0f), beta(1.0f);
    Ray ray = camera_ray;
    bool delta_before = true;  // the camera, or a delta lobe: emission seen is counted whole
    float bsdf_pdf = 0.0f;     // of the direction that led here (non-delta)
    bool scattered = false;    // a non-delta lobe was drawn at some vertex before
    glm::vec3 from(0.0f);
    RayKind kind = RayKind::Camera;
    for (int bounce = 0;; ++bounce) {
        Hit hit;
        const bool found = bounce == 0 && first_known
                               ? first != nullptr
                               : timed_trace(counts, kind, 1, [&] { return scene_.intersect(ray, hit); });
        if (bounce == 0 && first_known && first) hit = *first;
        if (!found) {
            radiance += beta * scene_.data.background;  // the uniform environment
            break;
        }
        const Surface s = surface_at(scene_, ray, hit);
        const Material& m = *s.material;
        const glm::vec3 wo = -glm::normalize(ray.direction);
        if (max_component(m.emit) > 0.0f) {
            // A moving emitter is found by the sampled directions alone (PathLights, PhotonEmitter):
            // all of its light, caustics included, is counted here, whole.
            const float choice = lights_.choice_probability(hit.instance);
            if (delta_before) {
                if (!(scattered && emitter_caustics_to_photons_ && !scene_.motion.contains(hit.instance)))
                    radiance += beta * m.emit;
            } else if (!(choice > 0.0f)) {
                radiance += beta * m.emit;
            } else {
                // The same light could have been found by next-event estimation: weigh the two.
                const glm::vec3 to = s.point - from;
                const float d2 = glm::dot(to, to);
                // The light's density is per unit area of its true surface: the geometric normal
                // (a mesh's shading normal, interpolated, is not that surface's).
                const glm::vec3 n_light = normal_to_world(scene_.data.instances[hit.instance], s.object_normal);
                const float cos_light = std::abs(glm::dot(n_light, wo));
                const float pdf_light = choice * lights_.pdf_area(hit.instance, from, s.point, s.object_normal) * d2 / std::max(cos_light, 1e-12f);
                radiance += beta * m.emit * power_heuristic(bsdf_pdf, pdf_light);
            }
        }
        if (bounce == 1 && direct) {  // what the first bounce found, before the second vertex's own light
            *direct = radiance;
            direct = nullptr;
        }
        if (bounce >= max_bounces_) break;

        const Vertex v{s, Bsdf(m, s.diffuse, s.normal, wo), wo, ray.time};
        if (v.bsdf.black()) break;
        // The vertex's four dimensions at once. The choice's first coordinate picks the light, its
        // second plays Russian roulette below.
        const std::uint32_t dims[4] = {dimension::path(bounce, dimension::kPathChoice),
                                       dimension::path(bounce, dimension::kPathLightPoint),
                                       dimension::path(bounce, dimension::kPathLobe),
                                       dimension::path(bounce, dimension::kPathDirection)};
        glm::vec2 u[4];
        sampler.get2d(key, dims, u);
        const glm::vec2 choice = u[0], lobe = u[2];
        radiance += beta * next_event(v, bounce, choice, u[1], key, sampler, counts);

        const BsdfSample bs = v.bsdf.sample(lobe.x, u[3]);
        if (!bs.valid || max_component(bs.weight) <= 0.0f) break;
        beta *= bs.weight;
        delta_before = bs.delta;
        scattered = scattered || !bs.delta;
        bsdf_pdf = bs.pdf;
        from = s.point;
        ray = Ray{spawn(s.point, s.normal, bs.wi), bs.wi, ray.time};
        kind = glm::dot(bs.wi, s.normal) * glm::dot(wo, s.normal) >= 0.0f ? RayKind::Reflected : RayKind::Refracted;
        ++(kind == RayKind::Reflected ? counts.reflected : counts.refracted);

        // Russian roulette after the third bounce: a path whose weight has fallen goes on with
        // probability equal to its weight, and carries 1/that when it does.
        if (bounce >= 2) {
            const float q = max_component(beta);
            if (q < 1.0f) {
                if (choice.y >= q) break;
                beta /= q;
            }
        }
    }
    if (direct) *direct = radiance;  // the path ended before its second vertex's light: all of it is direct
    return radiance;
}

std::vector<Diagnostic> path_mode_warnings(const SceneData& scene, const std::vector<SourceLoc>& sources) {
    std::vector<Diagnostic> out;
    for (std::size_t i = 0; i < scene.materials.size() && i < sources.size(); ++i) {
        const float s = energy_scale(scene.materials[i]);
        if (s < 1.0f)
            out.push_back({Severity::Warning, sources[i],
                           "in path mode this material's diffuse + specular + reflect + transparent exceeds 1 (up to " +
                               std::to_string(1.0f / s) + "); the four are scaled down by that, so that no surface "
                               "creates light"});
    }
    // In the order of the file (the materials come in the order the instances were drawn), once per
    // place: files in the order they first appear, then line and column. The keys are made once (a
    // file name compared in every comparison took a fifth of a big scene's load).
    using Key = std::tuple<std::size_t, int, int>;
    std::vector<std::string_view> files;
    std::vector<std::pair<Key, std::size_t>> order;
    order.reserve(out.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        const SourceLoc& loc = out[i].loc;
        const std::size_t file = std::size_t(std::find(files.begin(), files.end(), std::string_view(loc.file)) - files.begin());
        if (file == files.size()) files.push_back(loc.file);
        order.push_back({Key{file, loc.line, loc.col}, i});
    }
    std::sort(order.begin(), order.end());  // by place, then by index: stable
    std::vector<Diagnostic> sorted;
    sorted.reserve(out.size());
    for (std::size_t k = 0; k < order.size(); ++k)
        if (k == 0 || order[k].first != order[k - 1].first) sorted.push_back(std::move(out[order[k].second]));
    return sorted;
}

}  // namespace whitted
