// Triangle meshes, whitted against Embree 3 on the same triangles and the same rays.
// One engine and one scene per process, so that each process's peak memory is its own:
//   mesh_bench --engine whitted|embree --scene big|instances --threads 1|2 [--passes 4]
//   mesh_bench --engine both --scene big|instances [--passes ROUNDS]   (ratios, interleaved: run_both)
//   --avx2 off: whitted's mesh walks in SSE steps, as on a CPU without AVX2
// Scenes (generated here, deterministic):
//   big:       one displaced UV sphere of 1,000,000 triangles (shared vertices), camera at 4 radii.
//   instances: a 10,000-triangle displaced sphere instanced 10,000 times (100 × 100 grid, random
//              rotation and scale), camera above the grid looking across it.
// Measured: build time (whitted: the mesh BVH and the top level, as accelerate() does; Embree:
// rtcCommitScene of the mesh scene and the instance scene, default quality), 640×480 primary rays
// (one ray at a time: whitted Scene::intersect, Embree rtcIntersect1) and a shadow ray from every
// hit toward a point light (Scene::occluded, rtcOccluded1), rays per second of wall time over
// several passes on the given threads, and memory: the structures' own bytes where the engine says
// (whitted: TriangleMesh::memory_bytes and MeshBvh::memory_bytes + the top level) and the process's peak RSS above what it
// was after generating the triangles (both engines copy the triangles into their own buffers).
// Never part of CI; see bench/RESULTS.md.
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/gtc/matrix_transform.hpp>

#include "accel/scene.h"
#include "flatten/flatten.h"
#include "accel/mesh_bvh.h"
#include "mesh/uv_sphere.h"

namespace {

using namespace whitted;
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

double rss_mb() {
    std::ifstream statm("/proc/self/statm");
    double pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * 4096.0 / 1e6;
}
double peak_rss_mb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss) / 1e3;  // kB
}

// A UV sphere of radius ~1 with rings × segments bands, displaced by smooth bumps (so that the
// BVH sees an uneven surface, not a perfect sphere).
TriangleMesh displaced_sphere(int rings, int segments) {
    return uv_sphere_mesh(rings, segments, [](const glm::vec3& d) {
        return 1.0f + 0.15f * std::sin(7 * d.x) * std::sin(5 * d.y + 1) * std::sin(6 * d.z + 0.5f);
    });
}

struct Setup {
    TriangleMesh mesh;
    std::vector<glm::mat4> placements;  // object → world
    glm::vec3 eye, focus, light;
};

Setup make_setup(const std::string& scene) {
    Setup s;
    if (scene == "big") {
        s.mesh = displaced_sphere(708, 708);  // 1,001,112 triangles
        s.placements.push_back(glm::mat4(1.0f));
        s.eye = {0.5f, 1.0f, 4.0f};
        s.focus = {0, 0, 0};
    } else {
        s.mesh = displaced_sphere(71, 71);  // 9,940 triangles
        std::mt19937 rng(16);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        for (int i = 0; i < 10000; ++i) {
            glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(3.0f * float(i % 100) - 150.0f, 0.0f,
                                                                    3.0f * float(i / 100) - 150.0f));
            m = glm::rotate(m, 6.2831853f * u(rng), glm::normalize(glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f)));
            s.placements.push_back(glm::scale(m, glm::vec3(0.6f + 0.8f * u(rng))));
        }
        s.eye = {-160.0f, 25.0f, -160.0f};
        s.focus = {0, 0, 0};
    }
    s.light = s.eye + glm::vec3(30.0f, 60.0f, -10.0f);
    return s;
}

constexpr int kWidth = 640, kHeight = 480;

std::vector<Ray> camera_rays(const Setup& s) {
    const glm::vec3 f = glm::normalize(s.focus - s.eye), r = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0))),
                    up = glm::cross(r, f);
    const float tan_half = std::tan(0.5f * glm::radians(45.0f)), aspect = float(kWidth) / kHeight;
    std::vector<Ray> rays;
    rays.reserve(kWidth * kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const float sx = (2 * (x + 0.5f) / kWidth - 1) * tan_half * aspect, sy = (1 - 2 * (y + 0.5f) / kHeight) * tan_half;
            rays.push_back(Ray{s.eye, glm::normalize(f + sx * r + sy * up)});
        }
    return rays;
}

double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Wall seconds, and the CPU seconds the workers actually ran: on a machine shared with other jobs
// the second is the steadier measure of the code's own speed (preemption does not count in it).
struct Timing {
    double wall = 0, cpu = 0;
};

template <class Body>
Timing run_parallel(std::size_t n, int threads, int passes, Body body) {
    std::atomic<std::size_t> next{0};
    const std::size_t chunk = 4096, chunks = (n + chunk - 1) / chunk;
    std::vector<double> cpu(std::size_t(threads), 0.0);
    const auto start = Clock::now();
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            const double c0 = thread_cpu_seconds();
            for (std::size_t c; (c = next.fetch_add(1)) < passes * chunks;) {
                const std::size_t k = c % chunks;
                body(k * chunk, std::min(n, (k + 1) * chunk));
            }
            cpu[std::size_t(t)] = thread_cpu_seconds() - c0;
        });
    for (auto& t : pool) t.join();
    Timing timing{seconds_since(start), 0.0};
    for (double c : cpu) timing.cpu += c;
    return timing;
}

struct Result {
    double build_s = 0, structure_mb = 0, rss_delta_mb = 0, peak_delta_mb = 0;
    double primary_per_s = 0, shadow_per_s = 0, hit_fraction = 0, lit_fraction = 0;
    double primary_per_cpu_s = 0, shadow_per_cpu_s = 0;  // rays per CPU second of the workers
};

int passes_option = 4;  // --passes: more for a profiler

// Shadow rays from every primary hit toward the light (origin nudged off the surface).
struct ShadowRay {
    Ray ray;
    float t_max;
};

// whitted's scene of the setup's triangles (moved out of it): the mesh and its placements.
SceneData whitted_scene(Setup& s) {
    SceneData flat;
    flat.materials.push_back(Material{});
    flat.meshes.push_back(std::move(s.mesh));
    for (const glm::mat4& m : s.placements) {
        Instance inst = make_instance(m, ShapeKind::Mesh, 0);
        inst.mesh = 0;
        flat.instances.push_back(inst);
    }
    return flat;
}

// A shadow ray from every hit toward the light, its origin nudged back off the surface.
std::vector<ShadowRay> shadow_rays(const Setup& s, const std::vector<Ray>& rays, const std::vector<float>& hit_t) {
    std::vector<ShadowRay> shadow;
    for (std::size_t i = 0; i < rays.size(); ++i)
        if (hit_t[i] >= 0.0f) {
            const glm::vec3 p = rays[i].at(hit_t[i]) - 1e-3f * rays[i].direction;
            shadow.push_back({Ray{p, s.light - p}, 1.0f});
        }
    return shadow;
}

Result run_whitted(Setup& s, const std::vector<Ray>& rays, int threads) {
    Result res;
    const double rss0 = rss_mb(), peak0 = peak_rss_mb();
    SceneData flat = whitted_scene(s);
    const auto t0 = Clock::now();
    const Scene scene = accelerate(std::move(flat), threads);
    res.build_s = seconds_since(t0);
    res.rss_delta_mb = rss_mb() - rss0;
    res.peak_delta_mb = peak_rss_mb() - peak0;
    res.structure_mb = double(scene.data.meshes[0].memory_bytes() + scene.mesh_bvhs[0].memory_bytes() + scene.data.instances.capacity() * sizeof(Instance) +
                              scene.bvh.nodes.capacity() * sizeof(Bvh4Node) +
                              scene.bvh.wide.nodes.capacity() * sizeof(Bvh8Node)) / 1e6;
    std::vector<Hit> hits(rays.size());
    std::vector<char> found(rays.size());
    const Timing tp = run_parallel(rays.size(), threads, passes_option, [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) found[i] = scene.intersect(rays[i], hits[i]);
    });
    res.primary_per_s = passes_option * double(rays.size()) / tp.wall;
    res.primary_per_cpu_s = passes_option * double(rays.size()) / tp.cpu;
    std::vector<float> hit_t(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) hit_t[i] = found[i] ? hits[i].t : -1.0f;
    const std::vector<ShadowRay> shadow = shadow_rays(s, rays, hit_t);
    res.hit_fraction = double(shadow.size()) / double(rays.size());
    std::vector<char> blocked(shadow.size());
    const Timing ts = run_parallel(shadow.size(), threads, passes_option, [&](std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i) blocked[i] = scene.occluded(shadow[i].ray, shadow[i].t_max);
    });
    res.shadow_per_s = passes_option * double(shadow.size()) / ts.wall;
    res.shadow_per_cpu_s = passes_option * double(shadow.size()) / ts.cpu;
    std::size_t lit = 0;
    for (char c : blocked) lit += !c;
    res.lit_fraction = double(lit) / double(std::max<std::size_t>(1, shadow.size()));
    return res;
}

// Embree's scene of the setup's triangles: the mesh scene, and for several placements a scene of
// instances of it over it (`top`, else the mesh scene itself).
RTCScene embree_scene(RTCDevice device, const Setup& s, RTCScene& mesh_scene) {
    mesh_scene = rtcNewScene(device);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), s.mesh.positions.size()));
    std::memcpy(v, s.mesh.positions.data(), s.mesh.positions.size() * 3 * sizeof(float));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), s.mesh.triangles.size()));
    std::memcpy(idx, s.mesh.triangles.data(), s.mesh.triangles.size() * 3 * sizeof(unsigned));
    rtcCommitGeometry(g);
    rtcAttachGeometry(mesh_scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(mesh_scene);
    RTCScene top = mesh_scene;
    if (s.placements.size() > 1) {
        top = rtcNewScene(device);
        for (const glm::mat4& m : s.placements) {
            RTCGeometry inst = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
            rtcSetGeometryInstancedScene(inst, mesh_scene);
            rtcSetGeometryTransform(inst, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &m[0][0]);
            rtcCommitGeometry(inst);
            rtcAttachGeometry(top, inst);
            rtcReleaseGeometry(inst);
        }
        rtcCommitScene(top);
    }
    return top;
}

// Embree's nearest hit distance for one camera ray, −1 for none.
float embree_hit_t(RTCScene top, RTCIntersectContext& ctx, const Ray& ray) {
    RTCRayHit rh{};
    rh.ray.org_x = ray.origin.x, rh.ray.org_y = ray.origin.y, rh.ray.org_z = ray.origin.z;
    rh.ray.dir_x = ray.direction.x, rh.ray.dir_y = ray.direction.y, rh.ray.dir_z = ray.direction.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = INFINITY;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(top, &ctx, &rh);
    return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID ? rh.ray.tfar : -1.0f;
}

// Embree's answer for one shadow ray.
bool embree_occluded(RTCScene top, RTCIntersectContext& ctx, const ShadowRay& s) {
    RTCRay r{};
    r.org_x = s.ray.origin.x, r.org_y = s.ray.origin.y, r.org_z = s.ray.origin.z;
    r.dir_x = s.ray.direction.x, r.dir_y = s.ray.direction.y, r.dir_z = s.ray.direction.z;
    r.tnear = 0.0f;
    r.tfar = s.t_max;
    r.mask = ~0u;
    rtcOccluded1(top, &ctx, &r);
    return r.tfar < 0.0f;  // Embree sets tfar = -inf when occluded
}

Result run_embree(Setup& s, const std::vector<Ray>& rays, int threads) {
    Result res;
    const double rss0 = rss_mb(), peak0 = peak_rss_mb();
    const std::string config = "threads=" + std::to_string(threads);
    RTCDevice device = rtcNewDevice(config.c_str());
    const auto t0 = Clock::now();
    RTCScene mesh_scene = nullptr;
    RTCScene top = embree_scene(device, s, mesh_scene);
    res.build_s = seconds_since(t0);
    res.rss_delta_mb = rss_mb() - rss0;
    res.peak_delta_mb = peak_rss_mb() - peak0;
    res.structure_mb = 0;  // Embree does not say; see the RSS figures
    std::vector<float> hit_t(rays.size());
    const Timing tp = run_parallel(rays.size(), threads, passes_option, [&](std::size_t b, std::size_t e) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        for (std::size_t i = b; i < e; ++i) hit_t[i] = embree_hit_t(top, ctx, rays[i]);
    });
    res.primary_per_s = passes_option * double(rays.size()) / tp.wall;
    res.primary_per_cpu_s = passes_option * double(rays.size()) / tp.cpu;
    const std::vector<ShadowRay> shadow = shadow_rays(s, rays, hit_t);
    res.hit_fraction = double(shadow.size()) / double(rays.size());
    std::vector<char> blocked(shadow.size());
    const Timing ts = run_parallel(shadow.size(), threads, passes_option, [&](std::size_t b, std::size_t e) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        for (std::size_t i = b; i < e; ++i) {
            blocked[i] = embree_occluded(top, ctx, shadow[i]);
        }
    });
    res.shadow_per_s = passes_option * double(shadow.size()) / ts.wall;
    res.shadow_per_cpu_s = passes_option * double(shadow.size()) / ts.cpu;
    std::size_t lit = 0;
    for (char c : blocked) lit += !c;
    res.lit_fraction = double(lit) / double(std::max<std::size_t>(1, shadow.size()));
    if (top != mesh_scene) rtcReleaseScene(top);
    rtcReleaseScene(mesh_scene);
    rtcReleaseDevice(device);
    return res;
}


// --engine both: the two engines in one process, on the same rays (the shadow rays start at
// whitted's hits for both), timed alternately pass by pass: on a shared machine whose speed drifts
// from second to second, the per-pass ratio is far steadier than two processes' rates. Prints the
// median and range of the per-pass ratios whitted / Embree (rays per CPU-second); memory and build
// figures come from the one-engine runs.
void run_both(Setup& s, const std::vector<Ray>& rays, int rounds) {
    RTCDevice device = rtcNewDevice(std::getenv("EMBREE_CONFIG") ? std::getenv("EMBREE_CONFIG") : "threads=1");
    RTCScene mesh_scene = nullptr;
    RTCScene top = embree_scene(device, s, mesh_scene);
    SceneData flat = whitted_scene(s);
    const Scene scene = accelerate(std::move(flat), 1);

    std::vector<Hit> hits(rays.size());
    std::vector<char> found(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) found[i] = scene.intersect(rays[i], hits[i]);
    std::vector<float> hit_t(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) hit_t[i] = found[i] ? hits[i].t : -1.0f;
    const std::vector<ShadowRay> shadow = shadow_rays(s, rays, hit_t);
    std::vector<char> blocked(shadow.size());
    std::size_t sink = 0;  // results used, so that no pass is optimised away
    auto cpu_time = [](auto&& body) {
        const double c0 = thread_cpu_seconds();
        body();
        return thread_cpu_seconds() - c0;
    };
    auto whitted_primary = [&] {
        for (std::size_t i = 0; i < rays.size(); ++i) sink += scene.intersect(rays[i], hits[i]);
    };
    auto embree_primary = [&] {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        for (const Ray& ray : rays) sink += embree_hit_t(top, ctx, ray) >= 0.0f;
    };
    auto whitted_shadow = [&] {
        for (std::size_t i = 0; i < shadow.size(); ++i) blocked[i] = scene.occluded(shadow[i].ray, shadow[i].t_max);
    };
    auto embree_shadow = [&] {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        for (std::size_t i = 0; i < shadow.size(); ++i) {
            sink += embree_occluded(top, ctx, shadow[i]);
        }
    };
    whitted_primary(), embree_primary(), whitted_shadow(), embree_shadow();  // warm the caches
    std::vector<double> primary, shadow_ratio, w_primary, w_shadow;
    for (int k = 0; k < rounds; ++k) {
        // Alternate which engine goes first, so that neither always follows the other's cache state.
        const bool whitted_first = k % 2 == 0;
        double wp, ep, ws, es;
        if (whitted_first) wp = cpu_time(whitted_primary), ep = cpu_time(embree_primary);
        else ep = cpu_time(embree_primary), wp = cpu_time(whitted_primary);
        if (whitted_first) ws = cpu_time(whitted_shadow), es = cpu_time(embree_shadow);
        else es = cpu_time(embree_shadow), ws = cpu_time(whitted_shadow);
        primary.push_back(ep / wp);
        shadow_ratio.push_back(es / ws);
        w_primary.push_back(double(rays.size()) / wp / 1e6);
        w_shadow.push_back(double(shadow.size()) / ws / 1e6);
    }
    auto median = [](std::vector<double> x) {
        std::sort(x.begin(), x.end());
        return x.size() % 2 ? x[x.size() / 2] : 0.5 * (x[x.size() / 2 - 1] + x[x.size() / 2]);
    };
    auto lo = [](const std::vector<double>& x) { return *std::min_element(x.begin(), x.end()); };
    auto hi = [](const std::vector<double>& x) { return *std::max_element(x.begin(), x.end()); };
    std::printf("both    %-9s threads 1, %d rounds: whitted / Embree, rays per CPU-s, median [range] | primary %.3f "
                "[%.3f-%.3f] (whitted %.2f M/s) | shadow %.3f [%.3f-%.3f] (whitted %.2f M/s) | %zu\n",
                s.placements.size() > 1 ? "instances" : "big", rounds, median(primary), lo(primary), hi(primary),
                median(w_primary), median(shadow_ratio), lo(shadow_ratio), hi(shadow_ratio), median(w_shadow),
                sink % 2);
    if (top != mesh_scene) rtcReleaseScene(top);
    rtcReleaseScene(mesh_scene);
    rtcReleaseDevice(device);
}

}  // namespace

int main(int argc, char** argv) {
    std::string engine = "whitted", scene = "big";
    int threads = 1;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--engine") engine = v;
        else if (k == "--scene") scene = v;
        else if (k == "--threads") threads = std::stoi(v);
        else if (k == "--passes") passes_option = std::max(1, std::stoi(v));
        else if (k == "--avx2") set_mesh_walks_use_avx2(v != "off");  // off: the SSE walks
        else {
            std::fprintf(stderr, "usage: mesh_bench --engine whitted|embree|both --scene big|instances --threads N [--passes P] [--avx2 off]\n");
            return 2;
        }
    }
    Setup s = make_setup(scene);
    const std::size_t triangles = s.mesh.triangles.size();
    const std::vector<Ray> rays = camera_rays(s);
    if (engine == "both") {
        run_both(s, rays, passes_option);
        return 0;
    }
    const Result r = engine == "embree" ? run_embree(s, rays, threads) : run_whitted(s, rays, threads);
    std::printf("%-7s %-9s threads %d: %zu triangles x %zu instances | build %.3f s | structure %.1f MB "
                "(%.1f B/triangle) | RSS +%.1f MB, peak +%.1f MB | primary %.2f Mrays/s, %.2f per CPU-s (hit %.3f) | "
                "shadow %.2f Mrays/s, %.2f per CPU-s (lit %.3f)\n",
                engine.c_str(), scene.c_str(), threads, triangles, s.placements.size(), r.build_s, r.structure_mb,
                r.structure_mb * 1e6 / double(triangles), r.rss_delta_mb, r.peak_delta_mb, r.primary_per_s / 1e6,
                r.primary_per_cpu_s / 1e6, r.hit_fraction, r.shadow_per_s / 1e6, r.shadow_per_cpu_s / 1e6,
                r.lit_fraction);
    return 0;
}
