// whitted against Embree 3 on the same scenes and the same rays, side by side in one process
// (Google Benchmark). Built only when CMake finds Embree (see bench/EMBREE.md); never part of CI.
//
// Scenes (bench/bench_scenes.h, the ones whitted_bench uses):
//   spheres1k: 1,000 randomly rotated, non-uniformly scaled spheres, 640×480 camera rays in the
//              renderer's 32×32-tile order; shadow rays from every primary hit toward the light.
//   grid1m:    1000×1000 grid of mixed shapes (cube, cylinder, cone, sphere), same camera size.
// whitted: intersect_nearest, glass_transmittance (the any-hit query with the glass filter), and intersect_nearest_packet where the checkout has it.
// Embree gets the same instances (after whitted's BVH reordering, so Embree's instance or primitive
// i is whitted's instance i), default build quality and flags, in three encodings:
//   embree_point: two-level; the unit sphere as RTC_GEOMETRY_TYPE_SPHERE_POINT (centre 0, radius
//                 0.5) instanced with each instance's object→world matrix; spheres only. Embree
//                 intersects it in instance space with the transformed direction, dividing by |d|²,
//                 so it is the exact ellipsoid under any affine map.
//   embree_user:  two-level; one RTC_GEOMETRY_TYPE_USER per shape kind whose callback is whitted's
//                 analytic intersector (shapes/unit_shape_math.h), instanced the same way: the only
//                 way to give Embree the cube, cylinder and cone exactly.
//   embree_flat:  one level; one user geometry whose primitive i is whitted's instance i, with
//                 whitted's tight padded box and its per-instance test.
// Packets: rtcIntersect4/8/16 on 2×2 / 4×2 / 4×4 pixel blocks, registered only if the device
// reports native support. Counters: "rays" = rays per second of wall time; "hit_fraction" /
// "blocked_fraction" must agree between engines; the check_* entries compare every ray's result.
// The device config string can be given in the environment: WHITTED_EMBREE_CONFIG="isa=avx2".
#include <atomic>
#include <bit>
#include <concepts>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <pmmintrin.h>
#include <xmmintrin.h>

#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include "accel/instance_geometry.h"
#include "accel/mesh_bvh.h"
#include "bench_scenes.h"
#include "integrator/glass_transmittance.h"
#if __has_include("accel/bvh_packet.h")
#include "accel/bvh_packet.h"  // whitted's own packet traversal, where this checkout has it
#endif
#include "shapes/unit_shape_math.h"

namespace whitted::bench {
namespace {

// As in whitted_bench: every timed iteration traces every ray kPasses times, so that waking the
// second vCPU is amortised as in a render, and the rays are shared in chunks of kChunk (two 32×32
// tiles, so a chunk holds whole pixel blocks).
constexpr int kPasses = 8;
constexpr std::size_t kChunk = 2048;

// WHITTED_BENCH_FTZ=1: the worker threads run with denormals flushed to zero (flush-to-zero and
// denormals-are-zero), which Embree recommends; off by default, as in whitted_bench and the renderer.
bool flush_denormals() {
    static const bool on = [] {
        const char* v = std::getenv("WHITTED_BENCH_FTZ");
        return v && *v && *v != '0';
    }();
    return on;
}

template <class Body>
void parallel_for(std::size_t n, int threads, Body body) {
    const std::size_t chunks = (n + kChunk - 1) / kChunk;  // per pass
    alignas(64) std::atomic<std::size_t> next{0};
    const bool ftz = flush_denormals();
    auto worker = [&next, chunks, n, body, ftz]() mutable {  // its own copy of body
        if (ftz) {  // per thread, for every engine alike
            _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
            _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
        }
        for (std::size_t c; (c = next.fetch_add(1)) < kPasses * chunks;) {
            const std::size_t begin = (c % chunks) * kChunk;
            body(begin, std::min(n, begin + kChunk));
        }
    };
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
}

double rss_mb() {
    std::ifstream statm("/proc/self/statm");
    double pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * 4096.0 / 1e6;
}

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// ---------------------------------------------------------------------------------------------
// Embree device and scenes

RTCDevice device() {
    static RTCDevice dev = [] {
        const char* config = std::getenv("WHITTED_EMBREE_CONFIG");
        RTCDevice d = rtcNewDevice(config);
        if (!d) {
            std::fprintf(stderr, "rtcNewDevice failed: error %d\n", int(rtcGetDeviceError(nullptr)));
            std::exit(1);
        }
        rtcSetDeviceErrorFunction(
            d,
            [](void*, RTCError code, const char* msg) {
                std::fprintf(stderr, "Embree error %d: %s\n", int(code), msg ? msg : "");
                std::exit(1);
            },
            nullptr);
        return d;
    }();
    return dev;
}

// Shape tests per ray, counted only while a check runs (single-threaded; off in timed runs).
bool g_counting = false;
std::uint64_t g_shape_tests = 0;
inline void count_shape_test() {
    if (g_counting) [[unlikely]]
        ++g_shape_tests;
}

// User geometry: whitted's analytic unit shape, the kind fixed at compile time so that the switch
// folds away as it does in whitted's traversal. Bounds padded as whitted pads its boxes.
template <ShapeKind K>
void user_bounds(const RTCBoundsFunctionArguments* a) {
    const float r = 0.5f * (1.0f + 1e-5f);
    *a->bounds_o = RTCBounds{-r, -r, -r, 0.0f, r, r, r, 0.0f};
}

template <ShapeKind K>
void user_intersect(const RTCIntersectFunctionNArguments* a) {
    RTCRayN* ray = RTCRayHitN_RayN(a->rayhit, a->N);
    RTCHitN* hit = RTCRayHitN_HitN(a->rayhit, a->N);
    for (unsigned i = 0; i < a->N; ++i) {
        if (a->valid[i] != -1) continue;
        count_shape_test();
        const glm::vec3 o(RTCRayN_org_x(ray, a->N, i), RTCRayN_org_y(ray, a->N, i), RTCRayN_org_z(ray, a->N, i));
        const glm::vec3 d(RTCRayN_dir_x(ray, a->N, i), RTCRayN_dir_y(ray, a->N, i), RTCRayN_dir_z(ray, a->N, i));
        const auto s = shape_math::intersect<float>(K, o, d);
        if (s.count == 0) continue;
        const float tnear = RTCRayN_tnear(ray, a->N, i), tfar = RTCRayN_tfar(ray, a->N, i);
        float t;
        if (s.t[0] > tnear && s.t[0] < tfar) t = s.t[0];
        else if (s.t[1] > tnear && s.t[1] < tfar) t = s.t[1];
        else continue;
        RTCRayN_tfar(ray, a->N, i) = t;
        RTCHitN_Ng_x(hit, a->N, i) = 0.0f;  // the normal is the shader's business, as in whitted
        RTCHitN_Ng_y(hit, a->N, i) = 0.0f;
        RTCHitN_Ng_z(hit, a->N, i) = 1.0f;
        RTCHitN_u(hit, a->N, i) = 0.0f;
        RTCHitN_v(hit, a->N, i) = 0.0f;
        RTCHitN_primID(hit, a->N, i) = a->primID;
        RTCHitN_geomID(hit, a->N, i) = a->geomID;
        RTCHitN_instID(hit, a->N, i, 0) = a->context->instID[0];
    }
}

template <ShapeKind K>
void user_occluded(const RTCOccludedFunctionNArguments* a) {
    for (unsigned i = 0; i < a->N; ++i) {
        if (a->valid[i] != -1) continue;
        const glm::vec3 o(RTCRayN_org_x(a->ray, a->N, i), RTCRayN_org_y(a->ray, a->N, i), RTCRayN_org_z(a->ray, a->N, i));
        const glm::vec3 d(RTCRayN_dir_x(a->ray, a->N, i), RTCRayN_dir_y(a->ray, a->N, i), RTCRayN_dir_z(a->ray, a->N, i));
        const auto s = shape_math::intersect<float>(K, o, d);
        if (s.count == 0) continue;
        const float tnear = RTCRayN_tnear(a->ray, a->N, i), tfar = RTCRayN_tfar(a->ray, a->N, i);
        if ((s.t[0] > tnear && s.t[0] < tfar) || (s.t[1] > tnear && s.t[1] < tfar))
            RTCRayN_tfar(a->ray, a->N, i) = -INFINITY;
    }
}

template <ShapeKind K>
RTCGeometry new_user_shape() {
    RTCGeometry g = rtcNewGeometry(device(), RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, 1);
    rtcSetGeometryBoundsFunction(g, user_bounds<K>, nullptr);
    rtcSetGeometryIntersectFunction(g, user_intersect<K>);
    rtcSetGeometryOccludedFunction(g, user_occluded<K>);
    return g;
}

// Flat: one user geometry whose primitive i is whitted's instance i, with whitted's padded tight
// world box as its bounds and whitted's per-instance test (world→object rows, then the analytic
// shape) as its intersector. Embree's BVH and traversal over exactly the boxes whitted's BVH is
// built from, without Embree's instancing (whose instance boxes are the transformed corners of
// the prototype's box, so looser for rotated shapes).
Bounds padded_world_bounds(const Instance& inst) {  // as whitted's build pads them
    Bounds b = world_bounds(inst);
    const glm::vec3 mag = glm::max(glm::abs(b.lo), glm::abs(b.hi));
    const glm::vec3 pad(1e-5f * std::max(std::max(mag.x, mag.y), mag.z) + 1e-30f);
    b.lo -= pad;
    b.hi += pad;
    return b;
}

void flat_bounds(const RTCBoundsFunctionArguments* a) {
    const Bounds b = padded_world_bounds(static_cast<const Instance*>(a->geometryUserPtr)[a->primID]);
    *a->bounds_o = RTCBounds{b.lo.x, b.lo.y, b.lo.z, 0.0f, b.hi.x, b.hi.y, b.hi.z, 0.0f};
}

void flat_intersect(const RTCIntersectFunctionNArguments* a) {
    const Instance& inst = static_cast<const Instance*>(a->geometryUserPtr)[a->primID];
    RTCRayN* ray = RTCRayHitN_RayN(a->rayhit, a->N);
    RTCHitN* hit = RTCRayHitN_HitN(a->rayhit, a->N);
    for (unsigned i = 0; i < a->N; ++i) {
        if (a->valid[i] != -1) continue;
        count_shape_test();
        const Ray world{{RTCRayN_org_x(ray, a->N, i), RTCRayN_org_y(ray, a->N, i), RTCRayN_org_z(ray, a->N, i)},
                        {RTCRayN_dir_x(ray, a->N, i), RTCRayN_dir_y(ray, a->N, i), RTCRayN_dir_z(ray, a->N, i)}};
        const Ray o = to_object_space(inst, world);
        const auto s = shape_math::intersect<float>(inst.kind, o.origin, o.direction);
        if (s.count == 0) continue;
        const float tnear = RTCRayN_tnear(ray, a->N, i), tfar = RTCRayN_tfar(ray, a->N, i);
        float t;
        if (s.t[0] > tnear && s.t[0] < tfar) t = s.t[0];
        else if (s.t[1] > tnear && s.t[1] < tfar) t = s.t[1];
        else continue;
        RTCRayN_tfar(ray, a->N, i) = t;
        RTCHitN_Ng_x(hit, a->N, i) = 0.0f;
        RTCHitN_Ng_y(hit, a->N, i) = 0.0f;
        RTCHitN_Ng_z(hit, a->N, i) = 1.0f;
        RTCHitN_u(hit, a->N, i) = 0.0f;
        RTCHitN_v(hit, a->N, i) = 0.0f;
        RTCHitN_primID(hit, a->N, i) = a->primID;
        RTCHitN_geomID(hit, a->N, i) = a->geomID;
        RTCHitN_instID(hit, a->N, i, 0) = RTC_INVALID_GEOMETRY_ID;
    }
}

void flat_occluded(const RTCOccludedFunctionNArguments* a) {
    const Instance& inst = static_cast<const Instance*>(a->geometryUserPtr)[a->primID];
    for (unsigned i = 0; i < a->N; ++i) {
        if (a->valid[i] != -1) continue;
        const Ray world{{RTCRayN_org_x(a->ray, a->N, i), RTCRayN_org_y(a->ray, a->N, i), RTCRayN_org_z(a->ray, a->N, i)},
                        {RTCRayN_dir_x(a->ray, a->N, i), RTCRayN_dir_y(a->ray, a->N, i), RTCRayN_dir_z(a->ray, a->N, i)}};
        const Ray o = to_object_space(inst, world);
        const auto s = shape_math::intersect<float>(inst.kind, o.origin, o.direction);
        if (s.count == 0) continue;
        const float tnear = RTCRayN_tnear(a->ray, a->N, i), tfar = RTCRayN_tfar(a->ray, a->N, i);
        if ((s.t[0] > tnear && s.t[0] < tfar) || (s.t[1] > tnear && s.t[1] < tfar))
            RTCRayN_tfar(a->ray, a->N, i) = -INFINITY;
    }
}

enum class Proto { Point, User, Flat };

struct EmbreeScene {
    RTCScene top = nullptr;
    RTCScene protos[4] = {};  // by ShapeKind
    double build_ms = 0;      // rtcCommitScene of the top level (one shot)
    double setup_ms = 0;      // creating the instance geometries
    double rss_delta_mb = 0;  // resident memory added by the whole Embree scene
    EmbreeScene() = default;
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;
    ~EmbreeScene() {
        if (top) rtcReleaseScene(top);
        for (RTCScene s : protos)
            if (s) rtcReleaseScene(s);
    }
};

RTCScene prototype(Proto proto, ShapeKind kind) {
    RTCGeometry g = nullptr;
    if (proto == Proto::Point) {
        if (kind != ShapeKind::Sphere) return nullptr;  // only the sphere is a native Embree primitive
        g = rtcNewGeometry(device(), RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
        v[0] = v[1] = v[2] = 0.0f;
        v[3] = 0.5f;  // whitted's unit sphere: radius 0.5
    } else {
        switch (kind) {
            case ShapeKind::Cube: g = new_user_shape<ShapeKind::Cube>(); break;
            case ShapeKind::Cylinder: g = new_user_shape<ShapeKind::Cylinder>(); break;
            case ShapeKind::Cone: g = new_user_shape<ShapeKind::Cone>(); break;
            case ShapeKind::Sphere: g = new_user_shape<ShapeKind::Sphere>(); break;
            case ShapeKind::Ellipsoid:  // not benchmarked against Embree
            case ShapeKind::Mesh: return nullptr;  // meshes: bench/mesh_bench.cpp
        }
    }
    rtcCommitGeometry(g);
    RTCScene s = rtcNewScene(device());
    rtcAttachGeometry(s, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(s);
    return s;
}

std::unique_ptr<EmbreeScene> build_embree(const std::vector<Instance>& instances, Proto proto) {
    const double rss0 = rss_mb();
    auto e = std::make_unique<EmbreeScene>();
    if (proto == Proto::Flat) {
        auto start = std::chrono::steady_clock::now();
        e->top = rtcNewScene(device());
        RTCGeometry g = rtcNewGeometry(device(), RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, unsigned(instances.size()));
        rtcSetGeometryUserData(g, const_cast<Instance*>(instances.data()));
        rtcSetGeometryBoundsFunction(g, flat_bounds, nullptr);
        rtcSetGeometryIntersectFunction(g, flat_intersect);
        rtcSetGeometryOccludedFunction(g, flat_occluded);
        rtcCommitGeometry(g);
        rtcAttachGeometry(e->top, g);
        rtcReleaseGeometry(g);
        e->setup_ms = ms_since(start);
        start = std::chrono::steady_clock::now();
        rtcCommitScene(e->top);  // the bounds callback runs here
        e->build_ms = ms_since(start);
        e->rss_delta_mb = rss_mb() - rss0;
        return e;
    }
    for (int k = 0; k < 4; ++k) e->protos[k] = prototype(proto, ShapeKind(k));
    auto start = std::chrono::steady_clock::now();
    e->top = rtcNewScene(device());  // defaults: RTC_BUILD_QUALITY_MEDIUM, no scene flags
    for (std::size_t i = 0; i < instances.size(); ++i) {
        RTCScene p = e->protos[int(instances[i].kind)];
        if (!p) {
            std::fprintf(stderr, "shape %s has no Embree prototype of this kind\n", shape_name(instances[i].kind));
            std::exit(1);
        }
        RTCGeometry g = rtcNewGeometry(device(), RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(g, p);
        const glm::mat4 m = object_to_world(instances[i]);  // the inverse of whitted's world_to_object
        rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &m[0][0]);
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(e->top, g, unsigned(i));  // instID = whitted's instance index
        rtcReleaseGeometry(g);
    }
    e->setup_ms = ms_since(start);
    start = std::chrono::steady_clock::now();
    rtcCommitScene(e->top);
    e->build_ms = ms_since(start);
    e->rss_delta_mb = rss_mb() - rss0;
    return e;
}

// ---------------------------------------------------------------------------------------------
// Fixtures: whitted's scene and rays, and the Embree scenes built from the same instances.

struct Fixture {
    Scene scene;
    double whitted_build_ms = 0;
    std::vector<Ray> primary;                     // tile order, as whitted_bench
    std::vector<std::uint32_t> block[3];          // primary indices in 2×2, 4×2, 4×4 block order
    std::vector<Ray> shadow;                      // from the primary hits toward the light
    std::vector<float> shadow_reach;
    std::vector<std::uint32_t> shadow_from;       // the instance whose surface each starts on
    std::unique_ptr<EmbreeScene> point, user, flat;
};

// The rays of each 32×32 tile are consecutive, row by row; this lists them block by block
// (bw × bh pixels, lanes row by row), so that N consecutive entries are one packet.
std::vector<std::uint32_t> block_order(int width, int height, int bw, int bh, int tile = 32) {
    std::vector<std::uint32_t> order;
    order.reserve(std::size_t(width) * height);
    std::uint32_t base = 0;
    for (int ty = 0; ty < height; ty += tile)
        for (int tx = 0; tx < width; tx += tile) {
            const int tw = std::min(tile, width - tx), th = std::min(tile, height - ty);
            if (tw % bw || th % bh) {
                std::fprintf(stderr, "image size must be a multiple of the block size\n");
                std::exit(1);
            }
            for (int by = 0; by < th; by += bh)
                for (int bx = 0; bx < tw; bx += bw)
                    for (int y = by; y < by + bh; ++y)
                        for (int x = bx; x < bx + bw; ++x) order.push_back(base + std::uint32_t(y * tw + x));
            base += std::uint32_t(tw * th);
        }
    return order;
}

std::unique_ptr<Fixture> make_fixture(SceneData flat, int width, int height, bool with_point) {
    auto f = std::make_unique<Fixture>();
    auto start = std::chrono::steady_clock::now();
    f->scene = accelerate(std::move(flat));
    f->whitted_build_ms = ms_since(start);
    f->primary = camera_rays(f->scene.data.camera, width, height);
    f->block[0] = block_order(width, height, 2, 2);
    f->block[1] = block_order(width, height, 4, 2);
    f->block[2] = block_order(width, height, 4, 4);
    const glm::vec3 light = f->scene.data.lights[0].position;
    for (const Ray& r : f->primary) {  // exactly as whitted_bench makes its shadow rays
        Hit hit;
        if (!intersect_nearest(f->scene.bvh, f->scene.data.instances, r, 0.0f, INFINITY, hit)) continue;
        glm::vec3 p = r.at(hit.t);
        glm::vec3 to_light = light - p;
        float d = glm::length(to_light);
        glm::vec3 dir = to_light / d;
        f->shadow.push_back(Ray{p + 1e-3f * dir, dir});
        f->shadow_reach.push_back(d - 1e-3f);
        f->shadow_from.push_back(hit.instance);
    }
    if (with_point) f->point = build_embree(f->scene.data.instances, Proto::Point);
    f->user = build_embree(f->scene.data.instances, Proto::User);
    f->flat = build_embree(f->scene.data.instances, Proto::Flat);
    return f;
}

Fixture& spheres_1k() {
    static Fixture* f = make_fixture(random_scene(1000, false), 640, 480, true).release();  // kept to the end
    return *f;
}
Fixture& grid_1m() {
    static Fixture* f = make_fixture(grid_scene(1000), 640, 480, false).release();
    return *f;
}

// ---------------------------------------------------------------------------------------------
// Tracing one batch of rays with each engine. Each returns the number of hits (or blockers) in
// [b, e) and, if out is given, stores every ray's t (or -1 for a miss) and instance.

struct Result {
    float t;
    std::uint32_t instance;
};

// whitted's instance index: the Embree instance, or for the flat scene the primitive.
std::uint32_t hit_instance(unsigned inst_id, unsigned prim_id) {
    return inst_id != RTC_INVALID_GEOMETRY_ID ? inst_id : prim_id;
}

void init_ray(RTCRay& r, const Ray& ray, float tfar) {
    r.org_x = ray.origin.x; r.org_y = ray.origin.y; r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x; r.dir_y = ray.direction.y; r.dir_z = ray.direction.z;
    r.tnear = 0.0f;
    r.tfar = tfar;
    r.time = 0.0f;
    r.mask = ~0u;
    r.id = 0;
    r.flags = 0;
}

std::uint64_t trace_whitted(const Scene& s, const Ray* rays, std::size_t b, std::size_t e, Result* out) {
    std::uint64_t n = 0;
    for (std::size_t i = b; i < e; ++i) {
        Hit hit;
        const bool h = intersect_nearest(s.bvh, s.data.instances, rays[i], 0.0f, INFINITY, hit);
        n += h;
        if (out) out[i] = h ? Result{hit.t, hit.instance} : Result{-1.0f, ~0u};
    }
    return n;
}

std::uint64_t trace_embree1(RTCScene scene, const Ray* rays, std::size_t b, std::size_t e, Result* out) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // camera rays
    std::uint64_t n = 0;
    for (std::size_t i = b; i < e; ++i) {
        RTCRayHit rh;
        init_ray(rh.ray, rays[i], INFINITY);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &ctx, &rh);
        const bool h = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        n += h;
        if (out) out[i] = h ? Result{rh.ray.tfar, hit_instance(rh.hit.instID[0], rh.hit.primID)} : Result{-1.0f, ~0u};
    }
    return n;
}

// whitted's own packet query, if this checkout has it: intersect_nearest_packet(bvh, instances,
// const Ray (&)[N], unsigned active, t_min, t_max, Hit (&)[N]) -> unsigned hit mask, for N = 16,
// 8 or 4 (traced on the same 4×4, 4×2 or 2×2 pixel blocks as Embree's packets). Detected with a
// requires-expression, so that a checkout without it (or with another signature) still builds
// and only leaves it out.
template <int N, class B = Bvh>
constexpr bool kWhittedPacketN = requires(const B& bvh, const std::vector<Instance>& inst, const Ray (&rays)[N],
                                          unsigned active, Hit (&hits)[N]) {
    { intersect_nearest_packet(bvh, inst, rays, active, 0.0f, 0.0f, hits) } -> std::convertible_to<unsigned>;
};

template <class B = Bvh>
constexpr int whitted_packet_size() {
    if constexpr (kWhittedPacketN<16, B>) return 16;
    else if constexpr (kWhittedPacketN<8, B>) return 8;
    else if constexpr (kWhittedPacketN<4, B>) return 4;
    else return 0;
}
constexpr int kWhittedPacket = whitted_packet_size();  // 0: not in this checkout

template <int N, class B = Bvh>
std::uint64_t trace_whitted_packet(const Scene& s, const Ray* rays, const std::uint32_t* order, std::size_t b,
                                   std::size_t e, Result* out) {
    std::uint64_t n = 0;
    if constexpr (N > 0) {
        const B& bvh = s.bvh;
        constexpr unsigned all = N == 32 ? ~0u : (1u << N) - 1;
        for (std::size_t p = b; p < e; p += N) {
            Ray packet[N];
            Hit hits[N];
            for (int k = 0; k < N; ++k) packet[k] = rays[order[p + k]];
            const unsigned mask = intersect_nearest_packet(bvh, s.data.instances, packet, all, 0.0f, INFINITY, hits);
            n += unsigned(std::popcount(mask));
            if (out)
                for (int k = 0; k < N; ++k)
                    out[order[p + k]] = (mask >> k) & 1 ? Result{hits[k].t, hits[k].instance} : Result{-1.0f, ~0u};
        }
    }
    return n;
}

template <int N> struct PacketTraits;
template <> struct PacketTraits<4> {
    using RayHit = RTCRayHit4;
    static void intersect(const int* v, RTCScene s, RTCIntersectContext* c, RayHit* r) { rtcIntersect4(v, s, c, r); }
};
template <> struct PacketTraits<8> {
    using RayHit = RTCRayHit8;
    static void intersect(const int* v, RTCScene s, RTCIntersectContext* c, RayHit* r) { rtcIntersect8(v, s, c, r); }
};
template <> struct PacketTraits<16> {
    using RayHit = RTCRayHit16;
    static void intersect(const int* v, RTCScene s, RTCIntersectContext* c, RayHit* r) { rtcIntersect16(v, s, c, r); }
};

// [b, e) are positions in the block order `order` (multiples of N: chunks hold whole blocks).
template <int N>
std::uint64_t trace_embree_packet(RTCScene scene, const Ray* rays, const std::uint32_t* order, std::size_t b,
                                  std::size_t e, Result* out) {
    using PT = PacketTraits<N>;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(64) int valid[N];
    for (int k = 0; k < N; ++k) valid[k] = -1;
    std::uint64_t n = 0;
    for (std::size_t p = b; p < e; p += N) {
        typename PT::RayHit rh;
        for (int k = 0; k < N; ++k) {
            const Ray& r = rays[order[p + k]];
            rh.ray.org_x[k] = r.origin.x; rh.ray.org_y[k] = r.origin.y; rh.ray.org_z[k] = r.origin.z;
            rh.ray.dir_x[k] = r.direction.x; rh.ray.dir_y[k] = r.direction.y; rh.ray.dir_z[k] = r.direction.z;
            rh.ray.tnear[k] = 0.0f;
            rh.ray.tfar[k] = INFINITY;
            rh.ray.time[k] = 0.0f;
            rh.ray.mask[k] = ~0u;
            rh.ray.id[k] = 0;
            rh.ray.flags[k] = 0;
            rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
        }
        PT::intersect(valid, scene, &ctx, &rh);
        for (int k = 0; k < N; ++k) {
            const bool h = rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
            n += h;
            if (out)
                out[order[p + k]] = h ? Result{rh.ray.tfar[k], hit_instance(rh.hit.instID[0][k], rh.hit.primID[k])}
                                      : Result{-1.0f, ~0u};
        }
    }
    return n;
}

std::uint64_t shadow_whitted(const Scene& s, const Ray* rays, const float* reach, std::size_t b, std::size_t e,
                             std::uint8_t* out) {
    std::uint64_t n = 0;
    for (std::size_t i = b; i < e; ++i) {
        const bool blocked =
            glass_transmittance(s, rays[i], reach[i]).x == 0.0f;
        n += blocked;
        if (out) out[i] = blocked;
    }
    return n;
}

std::uint64_t shadow_embree1(RTCScene scene, const Ray* rays, const float* reach, std::size_t b, std::size_t e,
                             std::uint8_t* out) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);  // incoherent (the default): shadow rays
    std::uint64_t n = 0;
    for (std::size_t i = b; i < e; ++i) {
        RTCRay r;
        init_ray(r, rays[i], reach[i]);
        rtcOccluded1(scene, &ctx, &r);
        const bool blocked = r.tfar < 0.0f;  // set to -inf on a hit
        n += blocked;
        if (out) out[i] = blocked;
    }
    return n;
}

// ---------------------------------------------------------------------------------------------
// Engines and the benchmarks

enum class Engine { Whitted, WhittedPacket, Embree1, Embree4, Embree8, Embree16 };

// Traces primary rays [b, e) (positions in tile order, or in block order for packets).
std::uint64_t trace_primary(Fixture& f, Engine engine, RTCScene es, std::size_t b, std::size_t e, Result* out) {
    const Ray* rays = f.primary.data();
    switch (engine) {
        case Engine::Whitted: return trace_whitted(f.scene, rays, b, e, out);
        case Engine::WhittedPacket: {
            const int blk = kWhittedPacket == 4 ? 0 : kWhittedPacket == 8 ? 1 : 2;
            return trace_whitted_packet<kWhittedPacket>(f.scene, rays, f.block[blk].data(), b, e, out);
        }
        case Engine::Embree1: return trace_embree1(es, rays, b, e, out);
        case Engine::Embree4: return trace_embree_packet<4>(es, rays, f.block[0].data(), b, e, out);
        case Engine::Embree8: return trace_embree_packet<8>(es, rays, f.block[1].data(), b, e, out);
        case Engine::Embree16: return trace_embree_packet<16>(es, rays, f.block[2].data(), b, e, out);
    }
    return 0;
}

EmbreeScene& embree_of(Fixture& f, Proto proto) {
    return proto == Proto::Point ? *f.point : proto == Proto::User ? *f.user : *f.flat;
}
RTCScene embree_scene(Fixture& f, Proto proto) { return embree_of(f, proto).top; }

void bm_primary(benchmark::State& state, Fixture& (*fixture)(), Engine engine, Proto proto) {
    Fixture& f = fixture();
    RTCScene es = engine == Engine::Whitted || engine == Engine::WhittedPacket ? nullptr : embree_scene(f, proto);
    const int threads = int(state.range(0));
    alignas(64) std::atomic<std::uint64_t> hits{0};
    for (auto _ : state) {
        Fixture* fp = &f;
        std::atomic<std::uint64_t>* total = &hits;
        parallel_for(f.primary.size(), threads,
                     [=](std::size_t b, std::size_t e) { *total += trace_primary(*fp, engine, es, b, e, nullptr); });
    }
    const double rays = double(f.primary.size()) * kPasses * double(state.iterations());
    state.counters["rays"] = benchmark::Counter(rays, benchmark::Counter::kIsRate);
    state.counters["hit_fraction"] = double(hits) / rays;
}

void bm_shadow(benchmark::State& state, Fixture& (*fixture)(), Engine engine, Proto proto) {
    Fixture& f = fixture();
    RTCScene es = engine == Engine::Whitted ? nullptr : embree_scene(f, proto);
    const int threads = int(state.range(0));
    alignas(64) std::atomic<std::uint64_t> blocked{0};
    for (auto _ : state) {
        const Scene* s = &f.scene;
        const Ray* rays = f.shadow.data();
        const float* reach = f.shadow_reach.data();
        std::atomic<std::uint64_t>* total = &blocked;
        parallel_for(f.shadow.size(), threads, [=](std::size_t b, std::size_t e) {
            *total += es ? shadow_embree1(es, rays, reach, b, e, nullptr) : shadow_whitted(*s, rays, reach, b, e, nullptr);
        });
    }
    const double rays = double(f.shadow.size()) * kPasses * double(state.iterations());
    state.counters["rays"] = benchmark::Counter(rays, benchmark::Counter::kIsRate);
    state.counters["blocked_fraction"] = double(blocked) / rays;
}

// Every primary ray through whitted and through the Embree engine: hits must agree, and so must
// t (relative difference) and the instance hit. Also the shadow rays' blocked flags (single
// rays). One iteration; the counters are the report.
void bm_check(benchmark::State& state, Fixture& (*fixture)(), Engine engine, Proto proto) {
    Fixture& f = fixture();
    const bool is_embree = engine != Engine::WhittedPacket;  // else: whitted's packets against its single rays
    RTCScene es = embree_scene(f, proto);
    const EmbreeScene& esc = embree_of(f, proto);
    const std::size_t n = f.primary.size();
    std::vector<Result> ref(n), got(n);
    std::vector<std::uint8_t> sref(f.shadow.size()), sgot(f.shadow.size());
    for (auto _ : state) {
        trace_whitted(f.scene, f.primary.data(), 0, n, ref.data());
        g_counting = true;
        g_shape_tests = 0;
        trace_primary(f, engine, es, 0, n, got.data());
        g_counting = false;
        shadow_whitted(f.scene, f.shadow.data(), f.shadow_reach.data(), 0, f.shadow.size(), sref.data());
        if (is_embree) shadow_embree1(es, f.shadow.data(), f.shadow_reach.data(), 0, f.shadow.size(), sgot.data());
        else sgot = sref;  // whitted's packet query is for camera rays only
    }
    // The world-space chord (t_out - t_in) of `instance` along `ray`: tiny for a grazing ray.
    auto chord = [&f](const Ray& ray, std::uint32_t instance) {
        const Instance& inst = f.scene.data.instances[instance];
        const Ray o = to_object_space(inst, ray);
        const auto sp = shape_math::intersect<float>(inst.kind, o.origin, o.direction);
        return sp.count ? double(sp.t[1] - sp.t[0]) : 0.0;
    };
    std::size_t hit_w = 0, hit_e = 0, only_w = 0, only_e = 0, other_inst = 0, other_inst_same_t = 0, t_off = 0;
    double max_rel = 0, sum_rel = 0, differ_max_chord = 0, other_inst_max_chord = 0;
    std::size_t both = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const bool hw = ref[i].t >= 0, he = got[i].t >= 0;
        hit_w += hw;
        hit_e += he;
        if (hw != he) {
            ++(hw ? only_w : only_e);
            differ_max_chord = std::max(differ_max_chord, chord(f.primary[i], hw ? ref[i].instance : got[i].instance));
        }
        if (!(hw && he)) continue;
        ++both;
        const double rel = std::abs(double(got[i].t) - double(ref[i].t)) / double(ref[i].t);
        max_rel = std::max(max_rel, rel);
        sum_rel += rel;
        t_off += rel > 1e-4;
        if (got[i].instance != ref[i].instance) {
            ++other_inst;
            other_inst_same_t += rel <= 1e-4;  // two overlapping surfaces at (almost) the same t
            // The nearer of the two hit: did the other engine just graze past it?
            const std::uint32_t front = got[i].t < ref[i].t ? got[i].instance : ref[i].instance;
            other_inst_max_chord = std::max(other_inst_max_chord, chord(f.primary[i], front));
        }
    }
    std::size_t blk_w = 0, blk_e = 0, blk_diff = 0, blk_diff_not_self = 0;
    double blk_diff_max_t = 0;
    for (std::size_t i = 0; i < f.shadow.size(); ++i) {
        blk_w += sref[i] != 0;
        blk_e += sgot[i] != 0;
        if (sref[i] == sgot[i]) continue;
        ++blk_diff;
        // Which blocker did one engine find and the other not? A shadow ray starts 1e-3 off its
        // surface: if it leaves almost tangentially, whether it clips its own instance is decided
        // by rounding. A blocker other than that instance would be a real disagreement.
        Hit hw;
        const bool bw = intersect_nearest(f.scene.bvh, f.scene.data.instances, f.shadow[i], 0.0f, f.shadow_reach[i], hw);
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRayHit rh;
        init_ray(rh.ray, f.shadow[i], f.shadow_reach[i]);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(es, &ctx, &rh);
        const bool be = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        blk_diff_not_self += (bw && hw.instance != f.shadow_from[i]) ||
                             (be && hit_instance(rh.hit.instID[0], rh.hit.primID) != f.shadow_from[i]);
        blk_diff_max_t = std::max({blk_diff_max_t, bw ? double(hw.t) : 0.0, be ? double(rh.ray.tfar) : 0.0});
    }
    auto& c = state.counters;
    c["rays"] = double(n);
    // Instance (shape) tests per primary ray in the user and flat scenes: per lane, so for a packet
    // every active lane of a leaf test counts (the point sphere has no callback to count).
    if (is_embree) c["shape_tests_per_ray"] = proto == Proto::Point ? 0.0 : double(g_shape_tests) / double(n);
    c["hit_whitted"] = double(hit_w) / double(n);
    c["hit_embree"] = double(hit_e) / double(n);
    c["hit_only_whitted"] = double(only_w);
    c["hit_only_embree"] = double(only_e);
    c["hit_differ_max_chord"] = differ_max_chord;  // longest chord among the rays that differ
    c["t_max_rel_diff"] = max_rel;
    c["t_mean_rel_diff"] = both ? sum_rel / double(both) : 0.0;
    c["t_rel_diff_gt_1e-4"] = double(t_off);
    c["other_instance"] = double(other_inst);
    c["other_instance_same_t"] = double(other_inst_same_t);
    c["other_instance_max_chord"] = other_inst_max_chord;  // chord of the nearer instance
    c["shadow_rays"] = double(f.shadow.size());
    c["blocked_whitted"] = double(blk_w) / double(f.shadow.size());
    c["blocked_embree"] = double(blk_e) / double(f.shadow.size());
    c["blocked_differ"] = double(blk_diff);
    c["blocked_differ_max_t"] = blk_diff_max_t;  // the farthest blocker among the rays that differ
    c["blocked_differ_not_self"] = double(blk_diff_not_self);  // ... whose blocker is another instance
    c["build_ms_whitted"] = f.whitted_build_ms;
    if (!is_embree) return;
    c["build_ms_embree"] = esc.build_ms;
    c["setup_ms_embree"] = esc.setup_ms;
    c["MB_embree"] = esc.rss_delta_mb;
}

// A whitted benchmark with its walks in SSE where the CPU has AVX2 (the switch the walk tests
// turn): "_sse" beside the default, interleaved in one process.
template <auto Fn>
void with_sse(benchmark::State& state, Fixture& (*fixture)(), Engine engine, Proto proto) {
    set_mesh_walks_use_avx2(false);
    Fn(state, fixture, engine, proto);
    set_mesh_walks_use_avx2(true);
}

std::string engine_name(Engine e, Proto p) {
    if (e == Engine::Whitted) return "whitted_x1";
    if (e == Engine::WhittedPacket) return "whitted_x" + std::to_string(kWhittedPacket);
    std::string name = p == Proto::Point ? "embree_point" : p == Proto::User ? "embree_user" : "embree_flat";
    switch (e) {
        case Engine::Embree4: return name + "_x4";
        case Engine::Embree8: return name + "_x8";
        case Engine::Embree16: return name + "_x16";
        default: return name + "_x1";
    }
}

void register_all() {
    std::vector<Engine> engines{Engine::Embree1};
    if (rtcGetDeviceProperty(device(), RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED)) engines.push_back(Engine::Embree4);
    if (rtcGetDeviceProperty(device(), RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED)) engines.push_back(Engine::Embree8);
    if (rtcGetDeviceProperty(device(), RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED)) engines.push_back(Engine::Embree16);

    struct SceneDef {
        const char* name;
        Fixture& (*fixture)();
        std::vector<Proto> protos;
    };
    const SceneDef scenes[] = {{"spheres1k", spheres_1k, {Proto::Point, Proto::User, Proto::Flat}},
                               {"grid1m", grid_1m, {Proto::User, Proto::Flat}}};
    for (const SceneDef& s : scenes) {
        if constexpr (kWhittedPacket > 0) {
            std::string name = std::string("check_") + s.name + "/" + engine_name(Engine::WhittedPacket, Proto::User);
            benchmark::RegisterBenchmark(name.c_str(), bm_check, s.fixture, Engine::WhittedPacket, Proto::User)
                ->Iterations(1)
                ->Unit(benchmark::kMillisecond);
        }
        for (Proto p : s.protos)
            for (Engine e : engines) {
                std::string name = std::string("check_") + s.name + "/" + engine_name(e, p);
                benchmark::RegisterBenchmark(name.c_str(), bm_check, s.fixture, e, p)
                    ->Iterations(1)
                    ->Unit(benchmark::kMillisecond);
            }
    }
    for (const SceneDef& s : scenes) {
        auto add = [&](const char* kind, Engine e, Proto p, auto fn) {
            std::string name = std::string(kind) + "_" + s.name + "/" + engine_name(e, p);
            benchmark::RegisterBenchmark(name.c_str(), fn, s.fixture, e, p)
                ->ArgName("threads")
                ->Arg(1)
                ->Arg(2)
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
        };
        const bool avx2 = set_mesh_walks_use_avx2(true);
        auto add_sse = [&](const char* kind, Engine e, auto fn) {
            if (!avx2) return;
            std::string name = std::string(kind) + "_" + s.name + "/" + engine_name(e, Proto::User) + "_sse";
            benchmark::RegisterBenchmark(name.c_str(), fn, s.fixture, e, Proto::User)
                ->ArgName("threads")
                ->Arg(1)
                ->Arg(2)
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
        };
        add("primary", Engine::Whitted, Proto::User, bm_primary);
        add_sse("primary", Engine::Whitted, with_sse<bm_primary>);
        if constexpr (kWhittedPacket > 0) {
            add("primary", Engine::WhittedPacket, Proto::User, bm_primary);
            add_sse("primary", Engine::WhittedPacket, with_sse<bm_primary>);
        }
        for (Proto p : s.protos)
            for (Engine e : engines) add("primary", e, p, bm_primary);
        add("shadow", Engine::Whitted, Proto::User, bm_shadow);
        add_sse("shadow", Engine::Whitted, with_sse<bm_shadow>);
        for (Proto p : s.protos) add("shadow", Engine::Embree1, p, bm_shadow);
    }
}

}  // namespace
}  // namespace whitted::bench

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    whitted::bench::register_all();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;  // the fixtures and the device are left to the process exit
}
