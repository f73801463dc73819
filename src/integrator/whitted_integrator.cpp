#include "integrator/whitted_integrator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "integrator/glass_transmittance.h"
#include "sampler/warp.h"

namespace whitted {
namespace {

constexpr float kMinWeight = 1.0f / 256.0f;  // spec §7: rays weighing less are not traced
constexpr float kInfinity = std::numeric_limits<float>::infinity();

float max_component(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

// Refracts unit direction d through a surface with unit normal n facing d's origin side,
// eta = n_from / n_to. Returns false on total internal reflection.
bool refract(const glm::vec3& d, const glm::vec3& n, float eta, glm::vec3& out) {
    float cos_i = -glm::dot(n, d);
    float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);
    if (k < 0.0f) return false;
    out = glm::normalize(eta * d + (eta * cos_i - std::sqrt(k)) * n);
    return true;
}

}  // namespace

WhittedIntegrator::WhittedIntegrator(const Scene& scene, const Camera& camera, int max_depth,
                                     const Conventions& conventions)
    : Integrator(scene, camera), max_depth_(max_depth), conventions_(conventions), variant_(conventions.any()) {}

WhittedIntegrator::WhittedIntegrator(const Scene& scene, const Camera& camera, int max_depth,
                                     const Conventions& conventions, TextureFilter filter, float sample_rows)
    : WhittedIntegrator(scene, camera, max_depth, conventions) {
    filter_ = filter;
    if (uses_footprint(filter) && sample_rows > 0.0f) pitch_ = 2.0f * camera.tan_half_fov / sample_rows;
}

const RayDifferential* WhittedIntegrator::camera_differential(const Ray& ray, RayDifferential& rd) const {
    if (!(pitch_ > 0.0f)) return nullptr;
    rd = camera_.differential(ray, pitch_);
    return &rd;
}

glm::vec3 WhittedIntegrator::radiance(const Ray& ray, const SampleKey& key, const Sampler& sampler,
                                      RayCounts& counts) const {
    ++counts.camera;
    NoShadingRecorder none;
    RayDifferential rd;
    return trace(RayKind::Camera, ray, 0, glm::vec3(1.0f), SampleContext{sampler, key}, counts, none,
                 camera_differential(ray, rd));
}

glm::vec3 WhittedIntegrator::radiance(const Ray& ray, const SampleKey& key, const Sampler& sampler, RayCounts& counts,
                                      ShadingRecorder& recorder) const {
    ++counts.camera;
    RayDifferential rd;
    return trace(RayKind::Camera, ray, 0, glm::vec3(1.0f), SampleContext{sampler, key}, counts, recorder,
                 camera_differential(ray, rd));
}

glm::vec3 WhittedIntegrator::radiance(const Ray& ray, const SampleKey& key, const Sampler& sampler, RayCounts& counts,
                                      AovRecorder& recorder) const {
    ++counts.camera;
    RayDifferential rd;
    return trace(RayKind::Camera, ray, 0, glm::vec3(1.0f), SampleContext{sampler, key}, counts, recorder,
                 camera_differential(ray, rd));
}

// Whether the shadow query may start at the light. A hit found along a ray is off by about 1e-7
// of its distance from the ray's origin; from a light far away (relative to the scene around the
// point) that error would swallow the offset that keeps the point's own surface out of the query,
// so such lights are asked from the point. Decided the same way one ray at a time and in packets.
bool WhittedIntegrator::query_from_light(const Light& light, const LightSample& ls, const glm::vec3& start) {
    return light.type != LightType::Directional && glm::length(ls.position - start) * 1e-6f <= surface_offset(start);
}

// The light's sample for a point shaded at `depth`: its centre, or with an extent (§9.1) the point
// of it this sample draws. `centred`: the sampler's, asked once per shading rather than per light.
LightSample WhittedIntegrator::light_sample(const Light& light, std::size_t li, const glm::vec3& point, int depth,
                                            bool centred, const SampleContext& ctx) const {
    if (centred || !has_extent(light)) return sample_light(light, point);
    return sample_light(light, point, ctx.get2d(dimension::light(depth, std::uint32_t(li))));
}

// What reaches `start` (just off the lit side of a surface) from the light sample: 1 if nothing
// is in the way, 0 behind anything opaque, the product of the transparent colours crossed otherwise.
glm::vec3 WhittedIntegrator::shadow_factor(const Light& light, const LightSample& ls, const glm::vec3& start,
                                           float time) const {
    if (query_from_light(light, ls, start) && !conventions_.shadows_beyond_light) {
        // From the light to the point (t in (0, 1)): the nearest thing on the way decides it,
        // unless it is glass, whose every crossing on the way counts.
        Hit h;
        if (!scene_.intersect(Ray{ls.position, start - ls.position, time}, h, 1.0f)) return glm::vec3(1.0f);
        if (!scene_.material(h).is_transparent()) return glm::vec3(0.0f);
    }
    return through_glass(ls, start, time);
}

// The full query from the point toward the light: every transparent surface crossed tints it.
glm::vec3 WhittedIntegrator::through_glass(const LightSample& ls, const glm::vec3& start, float time) const {
    const float reach = std::isinf(ls.distance) || conventions_.shadows_beyond_light ? kInfinity
                                                                                     : glm::length(ls.position - start);
    if (conventions_.opaque_shadows) return glm::vec3(scene_.occluded(Ray{start, ls.to_light, time}, reach) ? 0.0f : 1.0f);
    return glass_transmittance(scene_, Ray{start, ls.to_light, time}, reach);
}

void WhittedIntegrator::radiance(const CameraBatch& batch, const Sampler& sampler, glm::vec3 (&out)[kPacketSize],
                                 RayCounts& counts) const {
    // A classic mistake made on purpose (whitted explain): its switches are read one ray at a time;
    // so are the rays that carry differentials.
    if (variant_ || pitch_ > 0.0f) {
        for (int l = 0; l < kPacketSize; ++l)
            if ((batch.active >> l) & 1) out[l] = radiance(batch.rays[l], batch.keys[l], sampler, counts);
        return;
    }
    const SceneData& flat = scene_.data;
    const unsigned active = batch.active;
    Hit hits[kPacketSize];
    const unsigned found =
        timed_trace(counts, RayKind::Camera, std::popcount(active), [&] { return scene_.intersect(batch.rays, active, hits); }) &
        active;
    ShadingPoint points[kPacketSize];
    for (int l = 0; l < kPacketSize; ++l)
        if ((found >> l) & 1) points[l] = shading_point(batch.rays[l], hits[l]);
    // The shadow rays toward each point or spot light, traced together from the light: they share
    // their origin and fan out over neighbouring points, as coherent as the camera rays were.
    // Exactly shadow_factor's first query, so the colours are those of one ray at a time. Lights
    // with a size are sampled per sample (no shared origin) and asked one by one.
    PacketQueries packet;
    const std::size_t packet_lights = std::min(flat.lights.size(), std::size_t(kPacketLights));
    for (std::size_t li = 0; li < packet_lights; ++li) {
        const Light& light = flat.lights[li];
        if (light.type == LightType::Directional || has_extent(light)) continue;
        Ray back[kPacketSize];
        unsigned want = 0;
        for (int l = 0; l < kPacketSize; ++l) {
            if (!((found >> l) & 1)) continue;
            const LightSample ls = sample_light(light, points[l].s.point);
            if (!faces_light(points[l], ls) || !query_from_light(light, ls, points[l].above))
                continue;  // not lit at all, or asked from the point (shadow_factor)
            back[l] = Ray{light.position, points[l].above - light.position, points[l].time};
            want |= 1u << l;
        }
        if (!want) continue;
        Hit blockers[kPacketSize];
        const unsigned blocked = timed_trace(counts, RayKind::Shadow, std::popcount(want),
                                             [&] { return scene_.intersect(back, want, blockers, 1.0f); });
        for (int l = 0; l < kPacketSize; ++l) {
            if (!((want >> l) & 1)) continue;
            packet.query[li][l] = !((blocked >> l) & 1)                         ? ShadowQuery::Lit
                                   : scene_.material(blockers[l]).is_transparent() ? ShadowQuery::Glass
                                                                                  : ShadowQuery::Blocked;
        }
    }
    // The reflections off opaque mirrors, traced together: neighbouring pixels' reflections off one
    // surface share the nodes they visit for a while. Exactly the ray shade_at traces first there:
    // the ideal direction (no gloss, or one sample), weight 1 · reflect, within the sample's budget.
    Ray mirrored[kPacketSize];
    for (int l = 0; l < kPacketSize && max_depth_ > 0; ++l) {
        if (!((found >> l) & 1)) continue;
        const ShadingPoint& p = points[l];
        const Material& m = *p.s.material;
        if (m.is_transparent() || !(max_component(m.reflect) >= kMinWeight) || (m.gloss > 0.0f && !sampler.centred()))
            continue;
        mirrored[l] = Ray{p.above, p.dir - 2.0f * glm::dot(p.dir, p.n) * p.n, p.time};
        packet.mirrored |= 1u << l;
    }
    if (packet.mirrored)
        packet.mirror_found = timed_trace(counts, RayKind::Reflected, std::popcount(packet.mirrored), [&] {
                                  return scene_.intersect(mirrored, packet.mirrored, packet.mirror_hit);
                              }) & packet.mirrored;
    NoShadingRecorder none;
    for (int l = 0; l < kPacketSize; ++l) {
        if (!((active >> l) & 1)) continue;
        ++counts.camera;
        out[l] = (found >> l) & 1 ? shade_at(points[l], 0, glm::vec3(1.0f), SampleContext{sampler, batch.keys[l]},
                                             counts, &packet, l, none)
                                  : flat.background;
    }
}

// Inlined where a reflected or refracted ray is traced, as it was before rays carried a time.
template <class Recorder>
[[gnu::always_inline]] inline glm::vec3 WhittedIntegrator::trace(RayKind kind, const Ray& ray, int depth, const glm::vec3& weight, const SampleContext& ctx,
                                   RayCounts& counts, Recorder& rec, const RayDifferential* rd) const {
    Hit hit;
    const bool found = timed_trace(counts, kind, 1, [&] { return scene_.intersect(ray, hit); });
    return shade_hit(ray, found ? &hit : nullptr, depth, weight, ctx, counts, rec, rd);
}

template <class Recorder>
[[gnu::always_inline]] inline glm::vec3 WhittedIntegrator::shade_hit(const Ray& ray, const Hit* found, int depth,
                                                                     const glm::vec3& weight, const SampleContext& ctx,
                                                                     RayCounts& counts, Recorder& rec,
                                                                     const RayDifferential* rd) const {
    if (!found) {
        rec.miss(scene_.data.background);
        return scene_.data.background;
    }
    const Hit& hit = *found;
    // The inspector's report gives every hit its texture coordinates, textured or not.
    auto record_hit = [&](const ShadingPoint& p) {
        if constexpr (Recorder::kRecords) {
            Surface s = p.s;
            if (Recorder::kReadsUv && s.material->texture < 0) s.uv = surface_uv(scene_, ray, hit);
            rec.hit(ray, hit, s, p.n, p.outside, depth);
        }
    };
    if (rd) {  // (apart, so that the common path keeps no differentials on its stack)
        Differentials d{*rd, {}};
        const ShadingPoint p = shading_point(ray, hit, &d);
        record_hit(p);
        return shade_at(p, depth, weight, ctx, counts, nullptr, 0, rec, p.differentials ? &d : nullptr);
    }
    const ShadingPoint p = shading_point(ray, hit);
    record_hit(p);
    return shade_at(p, depth, weight, ctx, counts, nullptr, 0, rec);
}

WhittedIntegrator::ShadingPoint WhittedIntegrator::shading_point(const Ray& ray, const Hit& hit,
                                                                 Differentials* d) const {
    ShadingPoint p;
    p.s = surface_at(scene_, ray, hit);
    p.time = ray.time;
    if (filter_ != TextureFilter::Bilinear) filter_texture(p, hit, d);
    if (variant_ && conventions_.normals_by_m)
        p.s.normal = normal_by_m(scene_.data.instances[hit.instance], p.s.object_normal);
    p.dir = glm::normalize(ray.direction);
    p.outside = glm::dot(p.s.normal, -p.dir) >= 0.0f;
    p.n = p.outside ? p.s.normal : -p.s.normal;  // faces the viewer: lighting only
    const float offset = variant_ && conventions_.no_offset ? 0.0f : surface_offset(p.s.point);
    p.above = p.s.point + offset * p.n;  // the viewer's side of the surface
    p.below = p.s.point - offset * p.n;
    return p;
}

// The texture read again with the filter asked for, over the hit's footprint when the ray has
// differentials (their hit's SurfaceDifferentials also carry them on through mirrors and glass).
void WhittedIntegrator::filter_texture(ShadingPoint& p, const Hit& hit, Differentials* d) const {
    p.differentials = d && surface_differentials(scene_, hit, p.s, d->ray, d->surface, p.time);
    refilter_texture(scene_, p.s, filter_, p.differentials ? &d->surface.uv : nullptr);
}

// Whether `light` lights the point at all (before shadows): facing it, and not out of its cone.
bool WhittedIntegrator::faces_light(const ShadingPoint& p, const LightSample& ls) {
    return glm::dot(p.n, ls.to_light) > 0.0f && max_component(ls.intensity) > 0.0f;
}

bool WhittedIntegrator::secondary_direction(const glm::vec3& ideal, const glm::vec3& n, bool above, float gloss,
                                            std::uint32_t dim, const SampleContext& ctx, glm::vec3& out) const {
    if (!(gloss > 0.0f) || ctx.sampler.centred()) {
        out = ideal;
        return true;
    }
    out = cosine_power_lobe(ideal, gloss, ctx.get2d(dim));
    const float side = glm::dot(out, n);
    return above ? side > 0.0f : side < 0.0f;
}

template <class Recorder>
glm::vec3 WhittedIntegrator::shade_at(const ShadingPoint& p, int depth, const glm::vec3& weight,
                                      const SampleContext& ctx, RayCounts& counts, const PacketQueries* packet,
                                      int lane, Recorder& rec, const Differentials* diff) const {
    const SceneData& flat = scene_.data;
    const Surface& s = p.s;
    const Material& m = *s.material;
    // References, not copies: the vectors live in `p` across the calls below either way (no
    // vector register survives a call), so copying them only adds stores.
    const glm::vec3 &dir = p.dir, &n = p.n, &above = p.above, &below = p.below;
    const glm::vec3 to_eye = -dir;
    const bool outside = p.outside;

    glm::vec3 color = m.emit + s.ambient * flat.ambient_intensity;
    rec.base(m.emit, s.ambient * flat.ambient_intensity);

    // Read once: as far as GCC knows, the calls in the loop could change them.
    const Light* const lights = flat.lights.data();
    const std::size_t light_count = flat.lights.size();
    const bool centred = ctx.sampler.centred();
    const std::size_t packet_lights = packet ? std::min(light_count, kPacketLights) : 0;  // known for lights below
    for (std::size_t li = 0; li < light_count; ++li) {
        const Light& light = lights[li];
        const LightSample ls = light_sample(light, li, s.point, depth, centred, ctx);
        if (!faces_light(p, ls)) {
            if constexpr (Recorder::kRecords) rec.light(LightTerm{li, ls, false, 0.0f, glm::vec3(0.0f), {}, {}});
            continue;
        }
        const float n_dot_l = glm::dot(n, ls.to_light);
        ++counts.shadow;
        // Camera-ray hits ask from the light first (so that a packet's shadow rays can share an
        // origin, and one by one they get the same answer); deeper hits, whose shadow rays are
        // not traced in packets, go straight to the query from the point, faster for single rays.
        const ShadowQuery known = li < packet_lights ? packet->query[li][lane] : ShadowQuery::Unknown;
        const glm::vec3 shadow = known == ShadowQuery::Lit                  ? glm::vec3(1.0f)
                                 : known == ShadowQuery::Blocked            ? glm::vec3(0.0f)
                                 : li < 32 && (conventions_.unshadowed_lights >> li) & 1u ? glm::vec3(1.0f)
                                 : timed_trace(counts, RayKind::Shadow, 1, [&] {
                                       return known == ShadowQuery::Glass || depth > 0
                                                  ? through_glass(ls, above, p.time)
                                                  : shadow_factor(light, ls, above, p.time);
                                   });
        if (max_component(shadow) <= 0.0f) {
            if constexpr (Recorder::kRecords) rec.light(LightTerm{li, ls, true, n_dot_l, shadow, {}, {}});
            continue;
        }
        glm::vec3 r = 2.0f * n_dot_l * n - ls.to_light;
        float r_dot_v = glm::dot(r, to_eye);
        if (conventions_.blinn_phong) r_dot_v = glm::dot(n, glm::normalize(ls.to_light + to_eye));  // N·H in its place
        float spec = r_dot_v > 0.0f ? std::pow(r_dot_v, m.shine) : 0.0f;
        color += shadow * ls.intensity * (s.diffuse * n_dot_l + m.specular * spec);
        if constexpr (Recorder::kRecords)
            rec.light(LightTerm{li, ls, true, n_dot_l, shadow, shadow * ls.intensity * (s.diffuse * n_dot_l),
                                shadow * ls.intensity * (m.specular * spec)});
    }

    if (depth >= max_depth_) {
        rec.depth_limit();
        rec.done(color);
        return color;
    }

    glm::vec3 reflect_weight = m.reflect;
    if (m.is_transparent()) {
        // Snell's law against an outside of ior 1 (spec §7), using the true outward normal.
        float eta = outside ? 1.0f / m.ior : m.ior;
        glm::vec3 refracted;
        if (refract(dir, n, eta, refracted)) {
            glm::vec3 w = weight * m.transparent;
            glm::vec3 d;
            bool limited = false;
            if (max_component(w) >= kMinWeight &&
                secondary_direction(refracted, n, false, m.gloss, dimension::gloss_refract(depth), ctx, d) &&
                !(limited = !ctx.take_ray())) {
                ++counts.refracted;
                rec.secondary(SecondaryKind::Refract, SecondaryRecord::Outcome::Traced, Ray{below, d, p.time}, w);
                glm::vec3 c;
                if (diff) {
                    RayDifferential next;  // none from here on if an auxiliary ray is totally reflected
                    const bool carried = refracted_differential(s.point, n, outside ? 1.0f : -1.0f, eta, diff->ray,
                                                                diff->surface, next);
                    c = trace(RayKind::Refracted, Ray{below, d, p.time}, depth + 1, w, ctx, counts, rec, carried ? &next : nullptr);
                } else {
                    c = trace(RayKind::Refracted, Ray{below, d, p.time}, depth + 1, w, ctx, counts, rec);
                }
                color += m.transparent * c;
                rec.secondary_color(c, m.transparent * c);
            } else if constexpr (Recorder::kRecords) {
                rec.secondary(SecondaryKind::Refract,
                              limited                        ? SecondaryRecord::Outcome::RayLimit
                              : max_component(w) >= kMinWeight ? SecondaryRecord::Outcome::OffSurface
                                                               : SecondaryRecord::Outcome::TooWeak,
                              Ray{below, refracted, p.time}, w);
            }
        } else {
            if (!conventions_.no_total_internal_reflection)
                reflect_weight += m.transparent;  // total internal reflection: one mirror ray carries both
            rec.total_internal_reflection();
        }
    }
    if (max_component(reflect_weight) > 0.0f) {
        glm::vec3 w = weight * reflect_weight;
        glm::vec3 d;
        bool limited = false;
        if (max_component(w) >= kMinWeight &&
            secondary_direction(dir - 2.0f * glm::dot(dir, n) * n, n, true, m.gloss, dimension::gloss_reflect(depth),
                                ctx, d) &&
            !(limited = !ctx.take_ray())) {
            ++counts.reflected;
            rec.secondary(SecondaryKind::Reflect, SecondaryRecord::Outcome::Traced, Ray{above, d, p.time}, w);
            glm::vec3 c;
            if (diff) {
                const RayDifferential next =
                    reflected_differential(s.point, n, outside ? 1.0f : -1.0f, diff->ray, diff->surface);
                c = trace(RayKind::Reflected, Ray{above, d, p.time}, depth + 1, w, ctx, counts, rec, &next);
            } else if (packet && (packet->mirrored >> lane) & 1) {  // traced with the packet
                c = shade_hit(Ray{above, d, p.time}, (packet->mirror_found >> lane) & 1 ? &packet->mirror_hit[lane] : nullptr,
                              depth + 1, w, ctx, counts, rec, nullptr);
            } else {
                c = trace(RayKind::Reflected, Ray{above, d, p.time}, depth + 1, w, ctx, counts, rec);
            }
            color += reflect_weight * c;
            rec.secondary_color(c, reflect_weight * c);
        } else if constexpr (Recorder::kRecords) {
            rec.secondary(SecondaryKind::Reflect,
                          limited                        ? SecondaryRecord::Outcome::RayLimit
                          : max_component(w) >= kMinWeight ? SecondaryRecord::Outcome::OffSurface
                                                           : SecondaryRecord::Outcome::TooWeak,
                          Ray{above, dir - 2.0f * glm::dot(dir, n) * n, p.time}, w);
        }
    }
    rec.done(color);
    return color;
}

}  // namespace whitted
