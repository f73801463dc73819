#include "integrator/caustic_integrator.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "accel/scene.h"
#include "base/parallel_for.h"
#include "integrator/bsdf.h"
#include "integrator/light_sample.h"  // attenuation
#include "integrator/surface.h"
#include "integrator/whitted_integrator.h"  // surface_offset
#include "sampler/warp.h"

namespace whitted {
namespace {

constexpr float kAlpha = 2.0f / 3.0f;  // the share of photons kept per sample, in Knaus and Zwicker's terms
constexpr std::size_t kChunk = 4096;   // photons traced as one item of work
constexpr std::size_t kWave = 16;      // chunks traced before the budget is checked

// The camera side's own numbers at a delta bounce (slots the path tracer leaves unused).
constexpr std::uint32_t kCausticLobe = 5;

float max_component(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

glm::vec3 spawn(const glm::vec3& p, const glm::vec3& outward, const glm::vec3& w) {
    const float off = surface_offset(p);
    return p + (glm::dot(w, outward) > 0.0f ? off : -off) * outward;
}

// A photon's numbers: SplitMix64 from a hash of (seed and sample index, photon), independent of any thread.
class PhotonRandom {
public:
    PhotonRandom(std::uint64_t key, std::uint64_t index) : state_(mix(key * 0x9E3779B97F4A7C15ull ^ mix(index))) {}
    float next() { return float(mix(state_ += 0x9E3779B97F4A7C15ull) >> 40) * 0x1p-24f; }
    glm::vec2 next2() {
        const float a = next();
        return {a, next()};
    }

private:
    static std::uint64_t mix(std::uint64_t z) {
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    std::uint64_t state_;
};

}  // namespace

bool scene_has_caustic_paths(const SceneData& scene) {
    const bool emitter = std::any_of(scene.materials.begin(), scene.materials.end(),
                                     [](const Material& m) { return max_component(m.emit) > 0.0f; });
    if (scene.lights.empty() && !emitter) return false;
    return std::any_of(scene.materials.begin(), scene.materials.end(), has_delta_lobe);
}

CausticIntegrator::CausticIntegrator(const Scene& scene, const Camera& camera, const CausticSettings& settings)
    : Integrator(scene, camera), path_(scene, camera, settings.max_bounces), settings_(settings),
      emitter_(scene, settings.aim) {
    // The emitters' light that meets an ideal mirror or glass first is the photons' from here on.
    path_.leave_emitter_caustics_to_photons(true);
    const Bounds b = scene.bounds();
    const float diagonal = b.empty() ? 1.0f : glm::length(b.extent());
    r0_ = settings.radius > 0.0f ? settings.radius : std::max(1e-6f, diagonal / 500.0f);
}

float CausticIntegrator::radius_of_sample(int s) const {
    return r0_ * std::sqrt(std::pow(float(s) + 1.0f, kAlpha - 1.0f));
}

const PhotonMap& CausticIntegrator::photon_map(int s) const {
    static const PhotonMap empty;
    return s >= prepared_.begin && s < prepared_.end ? maps_[std::size_t(s - prepared_.begin)].map : empty;
}

bool CausticIntegrator::trace_photon(std::uint64_t key, std::uint64_t index, std::vector<Photon>& out) const {
    PhotonRandom rng(key, index);
    EmissionNumbers u;
    u.light = rng.next();
    u.point = rng.next2();
    u.dir = rng.next2();
    u.cone = rng.next();
    u.triangle = rng.next();
    u.side = rng.next();
    EmittedPhoton e = emitter_.emit(u);
    Ray ray = e.ray;
    // Over a shutter each photon has its own time (drawn last: a scene that does not move keeps
    // every photon it had), met by the moving objects as a camera sample's rays meet them.
    if (!scene_.motion.empty()) ray.time = rng.next();
    glm::vec3 beta = e.power;
    const float beta0 = max_component(beta);
    if (!(beta0 > 0.0f)) return false;
    bool reached = false;  // the first surface has a delta lobe
    float travelled = 0.0f;  // from the light, along the photon's path (unit directions: t is distance)
    for (int depth = 0; depth < settings_.max_bounces; ++depth) {
        Hit hit;
        if (!scene_.intersect(ray, hit)) return reached;
        const Surface s = surface_at(scene_, ray, hit);
        travelled += hit.t;
        const glm::vec3 wo = -ray.direction;
        const Bsdf bsdf(*s.material, s.diffuse, s.normal, wo);
        if (bsdf.black()) return reached;
        if (depth == 0) reached = bsdf.non_delta_probability() < 1.0f;
        // Light that lands first where a non-delta lobe takes it is the path tracer's (its
        // next-event estimate); from the second surface on, every photon counts.
        if (depth > 0 && bsdf.has_non_delta()) {
            // §6's attenuation over the distance the light travelled (as §7's shadow rays through
            // glass take it): the photons' own density already falls as 1/d², so att(d) · d².
            const float att = e.attenuated ? attenuation(e.falloff, travelled) * travelled * travelled : 1.0f;
            out.push_back({s.point, wo, beta * att});
        }
        const float u_lobe = rng.next();
        const glm::vec2 u = rng.next2();
        if (depth == 0 && u_lobe < bsdf.non_delta_probability()) return reached;
        const BsdfSample bs = bsdf.sample(u_lobe, u);
        if (!bs.valid || max_component(bs.weight) <= 0.0f) return reached;
        beta *= bs.weight;
        // §9.2 refracts radiance unscaled: flux crossing into a denser medium is squeezed into a
        // narrower cone, so a photon carries (η_from / η_to)² of it (it comes back on the way out).
        const bool crossed = glm::dot(bs.wi, s.normal) * glm::dot(wo, s.normal) < 0.0f;
        if (crossed && s.material->ior > 0.0f) {
            const float eta = glm::dot(wo, s.normal) >= 0.0f ? 1.0f / s.material->ior : s.material->ior;
            beta *= eta * eta;
        }
        if (depth >= 2) {
            const float q = std::min(1.0f, max_component(beta) / beta0);
            if (rng.next() >= q) return reached;
            beta /= q;
        }
        ray = Ray{spawn(s.point, s.normal, bs.wi), bs.wi, ray.time};
    }
    return reached;
}

bool CausticIntegrator::prepare(const SampleRange& range) const {
    if (range.begin == prepared_.begin && range.end == prepared_.end && range.seed == prepared_.seed) return true;
    maps_.clear();
    stats_ = {};
    prepared_ = {-1, -1, 0, 0, nullptr};
    const std::size_t samples = std::size_t(std::max(0, range.end - range.begin));
    const std::size_t per = emitter_.empty() ? 0 : std::size_t(settings_.photons_per_sample);
    // The budget, shared by the samples: each may store its share (at least one chunk's worth).
    const std::size_t cap = samples ? std::max(kChunk, settings_.max_stored / samples) : 0;
    const std::size_t chunks = (per + kChunk - 1) / kChunk;  // per sample
    std::vector<std::vector<Photon>> photons(samples);
    std::vector<std::size_t> emitted(samples, 0);
    std::vector<std::uint8_t> cut(samples, 0);
    std::vector<std::vector<Photon>> wave(kWave);
    std::vector<std::size_t> wave_reached(kWave);
    std::vector<std::size_t> reached(samples, 0);
    // Work items are (sample, chunk) pairs in order, traced a wave at a time on the job's threads,
    // then appended in order: sample k's chunks stop at the first that would pass its share.
    const std::size_t items = samples * chunks;
    for (std::size_t i0 = 0; i0 < items; i0 += kWave) {
        const std::size_t n = std::min(kWave, items - i0);
        std::atomic<bool> stopped{false};
        parallel_for(n, worker_count(range.threads, n), [&](std::size_t k, int) {
            wave[k].clear();
            wave_reached[k] = 0;
            const std::size_t item = i0 + k, sample = item / chunks, chunk = item % chunks;
            if (cut[sample]) return;
            if (range.cancel && range.cancel->load(std::memory_order_relaxed)) {
                stopped = true;
                return;
            }
            const std::uint64_t key = (std::uint64_t(range.seed) << 32) ^ std::uint64_t(range.begin + int(sample));
            const std::size_t from = chunk * kChunk, to = std::min(per, from + kChunk);
            for (std::size_t i = from; i < to; ++i) wave_reached[k] += trace_photon(key, i, wave[k]) ? 1 : 0;
        });
        if (stopped || (range.cancel && range.cancel->load())) {
            maps_.clear();
            return false;
        }
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t item = i0 + k, sample = item / chunks, chunk = item % chunks;
            if (cut[sample]) continue;
            if (photons[sample].size() + wave[k].size() > cap) {
                cut[sample] = 1;  // this chunk and the sample's later ones are not emitted
                continue;
            }
            photons[sample].insert(photons[sample].end(), wave[k].begin(), wave[k].end());
            reached[sample] += wave_reached[k];
            emitted[sample] = std::min(per, (chunk + 1) * kChunk);
        }
    }
    maps_.resize(samples);
    for (std::size_t k = 0; k < samples; ++k) {
        const float radius = radius_of_sample(range.begin + int(k));
        stats_.emitted += emitted[k];
        stats_.reached += reached[k];
        stats_.stored += photons[k].size();
        stats_.cut = stats_.cut || cut[k];
        maps_[k].map.build(std::move(photons[k]), radius);
        maps_[k].scale = emitted[k] > 0 ? 1.0f / (kPi * radius * radius * float(emitted[k])) : 0.0f;
        stats_.bytes += maps_[k].map.bytes();
    }
    stats_.radius = samples ? radius_of_sample(range.begin) : 0.0f;
    prepared_ = range;
    prepared_.cancel = nullptr;
    return true;
}

void CausticIntegrator::radiance(const CameraBatch& batch, const Sampler& sampler, glm::vec3 (&out)[kPacketSize],
                                 RayCounts& counts) const {
    Hit hits[kPacketSize];
    const unsigned found = timed_trace(counts, RayKind::Camera, std::popcount(batch.active),
                                       [&] { return scene_.intersect(batch.rays, batch.active, hits); });
    for (int l = 0; l < kPacketSize; ++l)
        if ((batch.active >> l) & 1) {
            const Hit* first = (found >> l) & 1 ? &hits[l] : nullptr;
            out[l] = path_.radiance(batch.rays[l], batch.keys[l], sampler, counts, first, true) +
                     caustic(batch.rays[l], batch.keys[l], sampler, counts, first, true);
        }
}

glm::vec3 CausticIntegrator::caustic(const Ray& camera_ray, const SampleKey& key, const Sampler& sampler,
                                     RayCounts& counts, const Hit* first, bool first_known) const {
    const int k = int(key.index) - prepared_.begin;
    if (k < 0 || k >= int(maps_.size()) || maps_[std::size_t(k)].map.size() == 0) return glm::vec3(0.0f);
    const SampleMap& sample_map = maps_[std::size_t(k)];
    Ray ray = camera_ray;
    glm::vec3 beta(1.0f);
    RayKind kind = RayKind::Camera;
    for (int bounce = 0; bounce < settings_.max_bounces; ++bounce) {
        Hit hit;
        const bool found = bounce == 0 && first_known
                               ? first != nullptr
                               : timed_trace(counts, kind, 1, [&] { return scene_.intersect(ray, hit); });
        if (!found) return glm::vec3(0.0f);
        if (bounce == 0 && first_known) hit = *first;
        const Surface s = surface_at(scene_, ray, hit);
        const glm::vec3 wo = -glm::normalize(ray.direction);
        const Bsdf bsdf(*s.material, s.diffuse, s.normal, wo);
        if (bsdf.black()) return glm::vec3(0.0f);
        // A non-delta lobe drawn here (with its probability): gather; a delta one: follow it.
        const glm::vec2 u = sampler.get2d(key, dimension::path(bounce, kCausticLobe));
        const float p_gather = bsdf.non_delta_probability();
        if (u.x < p_gather) {
            glm::vec3 sum(0.0f);
            sample_map.map.for_each_near(s.point, [&](const Photon& ph) { sum += bsdf.f(ph.wi) * ph.power; });
            return beta * sum * (sample_map.scale / p_gather);
        }
        const BsdfSample bs = bsdf.sample(u.x, u);  // a delta lobe: the direction needs no numbers
        if (!bs.valid || !bs.delta || max_component(bs.weight) <= 0.0f) return glm::vec3(0.0f);
        beta *= bs.weight;
        ray = Ray{spawn(s.point, s.normal, bs.wi), bs.wi, ray.time};
        kind = glm::dot(bs.wi, s.normal) * glm::dot(wo, s.normal) >= 0.0f ? RayKind::Reflected : RayKind::Refracted;
        ++(kind == RayKind::Reflected ? counts.reflected : counts.refracted);
    }
    return glm::vec3(0.0f);
}

}  // namespace whitted
