// Micro-benchmarks (Google Benchmark): BVH build, primary- and shadow-ray throughput, and a full
// render's thread scaling. Build with -DWHITTED_BUILD_BENCH=ON in Release; run build/bench/whitted_bench.
// Ray throughput is reported as the counter "rays" (rays per second of wall time); the /threads:N
// argument is the number of std::threads sharing each batch of rays.
#include <atomic>
#include <bit>
#include <memory>
#include <thread>

#include <benchmark/benchmark.h>
#include <stb/stb_image_write.h>

#include "accel/instance_geometry.h"
#include "bench_scenes.h"
#include "film/image.h"
#include "film/png_encode.h"
#include "integrator/glass_transmittance.h"
#include "render/load_scene.h"
#include "render/renderer.h"

namespace whitted::bench {
namespace {

// Each timed iteration traces every ray kPasses times, so that starting the threads (which can
// take milliseconds on a VM whose idle vCPU must be woken) is amortised as it is in a render.
constexpr int kPasses = 8;

// Runs body(begin, end) over [0, n) kPasses times, in chunks of `chunk` items shared by `threads`
// threads.
template <class Body>
void parallel_for(std::size_t n, int threads, Body body, std::size_t chunk = 2048) {
    const std::size_t chunks = (n + chunk - 1) / chunk;  // per pass
    alignas(64) std::atomic<std::size_t> next{0};  // own cache line: no false sharing with locals
    auto worker = [&next, chunks, chunk, n, body]() mutable {  // its own copy of body: nothing shared is read per ray
        for (std::size_t c; (c = next.fetch_add(1)) < kPasses * chunks;) {
            const std::size_t begin = (c % chunks) * chunk;
            body(begin, std::min(n, begin + chunk));
        }
    };
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();
}

struct Fixture {
    Scene scene;
    std::vector<Ray> primary;
    std::vector<CameraPacket> packets;  // the same camera rays, as the renderer's packets
    std::vector<Ray> shadow;         // from the primary hits toward the light
    std::vector<float> shadow_reach;
};

std::unique_ptr<Fixture> make_fixture(SceneData flat, int width, int height) {
    auto f = std::make_unique<Fixture>();
    f->scene = accelerate(std::move(flat));
    f->primary = camera_rays(f->scene.data.camera, width, height);
    f->packets = camera_packets(f->scene.data.camera, width, height);
    const glm::vec3 light = f->scene.data.lights[0].position;
    for (const Ray& r : f->primary) {
        Hit hit;
        if (!intersect_nearest(f->scene.bvh, f->scene.data.instances, r, 0.0f, INFINITY, hit)) continue;
        glm::vec3 p = r.at(hit.t);
        glm::vec3 to_light = light - p;
        float d = glm::length(to_light);
        // Start a little toward the light (as the integrator does along the normal).
        glm::vec3 dir = to_light / d;
        f->shadow.push_back(Ray{p + 1e-3f * dir, dir});
        f->shadow_reach.push_back(d - 1e-3f);
    }
    return f;
}

Fixture& spheres_1k() {
    static auto f = make_fixture(random_scene(1000, false), 640, 480);
    return *f;
}
Fixture& grid_1m() {
    static auto f = make_fixture(grid_scene(1000), 640, 480);
    return *f;
}

void primary(benchmark::State& state, Fixture& f) {
    const int threads = int(state.range(0));
    alignas(64) std::atomic<std::uint64_t> hits{0};
    for (auto _ : state) {
        const Bvh* bvh = &f.scene.bvh;
        const std::vector<Instance>* instances = &f.scene.data.instances;
        const Ray* rays = f.primary.data();
        std::atomic<std::uint64_t>* total = &hits;
        parallel_for(f.primary.size(), threads, [=](std::size_t b, std::size_t e) {
            std::uint64_t n = 0;
            for (std::size_t i = b; i < e; ++i) {
                Hit hit;
                n += intersect_nearest(*bvh, *instances, rays[i], 0.0f, INFINITY, hit);
            }
            *total += n;
        });
    }
    state.counters["rays"] = benchmark::Counter(double(f.primary.size()) * kPasses * state.iterations(), benchmark::Counter::kIsRate);
    state.counters["hit_fraction"] = double(hits) / (double(f.primary.size()) * kPasses * state.iterations());
}

// The same camera rays as primary(), traced kPacketSize at a time (intersect_nearest_packet).
void primary_packets(benchmark::State& state, Fixture& f) {
    const int threads = int(state.range(0));
    alignas(64) std::atomic<std::uint64_t> hits{0};
    for (auto _ : state) {
        const Bvh* bvh = &f.scene.bvh;
        const std::vector<Instance>* instances = &f.scene.data.instances;
        const CameraPacket* packets = f.packets.data();
        std::atomic<std::uint64_t>* total = &hits;
        parallel_for(f.packets.size(), threads, [=](std::size_t b, std::size_t e) {
            std::uint64_t n = 0;
            for (std::size_t i = b; i < e; ++i) {
                Hit hit[kPacketSize];
                n += std::popcount(intersect_nearest_packet(*bvh, *instances, packets[i].rays, packets[i].active, 0.0f,
                                                            INFINITY, hit));
            }
            *total += n;
        }, 2048 / kPacketSize);  // the same rays per chunk as primary()
    }
    state.counters["rays"] = benchmark::Counter(double(f.primary.size()) * kPasses * state.iterations(), benchmark::Counter::kIsRate);
    state.counters["hit_fraction"] = double(hits) / (double(f.primary.size()) * kPasses * state.iterations());
}

void shadow(benchmark::State& state, Fixture& f) {
    const int threads = int(state.range(0));
    alignas(64) std::atomic<std::uint64_t> blocked{0};
    for (auto _ : state) {
        const Scene* scene = &f.scene;
        const Ray* rays = f.shadow.data();
        const float* reach = f.shadow_reach.data();
        std::atomic<std::uint64_t>* total = &blocked;
        parallel_for(f.shadow.size(), threads, [=](std::size_t b, std::size_t e) {
            std::uint64_t n = 0;
            for (std::size_t i = b; i < e; ++i)
                n += glass_transmittance(*scene, rays[i], reach[i]).x == 0.0f;
            *total += n;
        });
    }
    state.counters["rays"] = benchmark::Counter(double(f.shadow.size()) * kPasses * state.iterations(), benchmark::Counter::kIsRate);
    state.counters["blocked_fraction"] = double(blocked) / (double(f.shadow.size()) * kPasses * state.iterations());
}

void BM_PrimarySpheres1k(benchmark::State& s) { primary(s, spheres_1k()); }
void BM_PrimarySpheres1kPacket(benchmark::State& s) { primary_packets(s, spheres_1k()); }
void BM_ShadowSpheres1k(benchmark::State& s) { shadow(s, spheres_1k()); }
void BM_PrimaryGrid1M(benchmark::State& s) { primary(s, grid_1m()); }
void BM_PrimaryGrid1MPacket(benchmark::State& s) { primary_packets(s, grid_1m()); }
void BM_ShadowGrid1M(benchmark::State& s) { shadow(s, grid_1m()); }

void BM_BvhBuild(benchmark::State& state) {
    const int n = int(state.range(0));
    int side = int(std::lround(std::sqrt(double(n))));
    const std::vector<Instance> source = grid_scene(side).instances;
    std::size_t nodes = 0;
    for (auto _ : state) {
        state.PauseTiming();
        std::vector<Instance> instances = source;
        state.ResumeTiming();
        Bvh bvh = build_bvh(instances);
        nodes = bvh.nodes.size();
        benchmark::DoNotOptimize(bvh.nodes.data());
    }
    state.counters["instances"] = double(source.size());
    state.counters["nodes"] = double(nodes);
    state.counters["MB"] = double(nodes * sizeof(Bvh4Node) + source.size() * sizeof(Instance)) / 1e6;
}

// The whole integrator (shadows, reflections) on a 1920×1080 image: thread scaling of render().
void BM_Render1080p(benchmark::State& state) {
    static Scene scene = [] {
        SceneData flat = random_scene(1000, true, 7);
        flat.materials[0].reflect = glm::vec3(0.3f);
        flat.materials[0].specular = glm::vec3(0.5f);
        flat.materials[0].shine = 30;
        flat.lights.push_back(Light{LightType::Point, {-30, 20, 30}, {0, -1, 0}, glm::vec3(0.5f)});
        return accelerate(std::move(flat));
    }();
    RenderJob o;
    o.width = 1920;
    o.height = 1080;
    o.threads = int(state.range(0));
    Image image(o.width, o.height);
    RayCounts rays;
    for (auto _ : state) rays += render(scene, o, image).rays;
    state.counters["rays"] = benchmark::Counter(double(rays.total()), benchmark::Counter::kIsRate);
}

// The bundled showcase with its §9.1 effects (disc light, lens, gloss) at 640×480: rays per second
// at 1 sample per pixel (every effect at its centre: the lab model) and at 16.
void BM_ShowcaseSpp(benchmark::State& state) {
    static const LoadResult loaded = load_scene(std::string(WHITTED_SCENES_DIR) + "/showcase.sc");
    if (!loaded.ok()) {
        state.SkipWithError("showcase.sc did not load");
        return;
    }
    RenderJob job;
    job.width = 640;
    job.height = 480;
    job.sampling.spp = int(state.range(0));
    job.threads = int(state.range(1));
    Image image(job.width, job.height);
    RayCounts rays;
    for (auto _ : state) rays += render(*loaded.scene, job, image).rays;
    state.counters["rays"] = benchmark::Counter(double(rays.total()), benchmark::Counter::kIsRate);
    state.counters["samples"] =
        benchmark::Counter(double(job.width) * job.height * job.sampling.spp * double(state.iterations()),
                           benchmark::Counter::kIsRate);
}

// PNG encoding of an 8K (7680 × 4320, 33 MP) render of the showcase, as an interrupted render
// writes it: the zlib encoder on 1 and 2 threads, and stb's (what whitted used before, at the
// settings it used: compression level 5, Sub filter). Throughput in MB/s of RGB pixels.
const Image& showcase_8k() {
    static const Image image = [] {
        LoadResult loaded = load_scene(std::string(WHITTED_SCENES_DIR) + "/showcase.sc");
        RenderJob job;
        job.width = 7680;
        job.height = 4320;
        Image img(job.width, job.height);
        if (loaded.ok()) render(*loaded.scene, job, img);
        return img;
    }();
    return image;
}

void BM_PngEncode8K(benchmark::State& state) {
    const Image& image = showcase_8k();
    std::size_t bytes = 0;
    for (auto _ : state) {
        bytes = 0;
        encode_png(image, [&](const void*, std::size_t n) { bytes += n; }, int(state.range(0)));
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(image.rgb.size()));
    state.counters["file_MB"] = double(bytes) / 1e6;
}

void BM_PngEncode8KStb(benchmark::State& state) {
    const Image& image = showcase_8k();
    stbi_write_png_compression_level = 5;
    stbi_write_force_png_filter = 1;
    std::size_t bytes = 0;
    for (auto _ : state) {
        bytes = 0;
        stbi_write_png_to_func([](void* c, void*, int n) { *static_cast<std::size_t*>(c) += std::size_t(n); }, &bytes,
                               image.width, image.height, 3, image.rgb.data(), image.width * 3);
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(image.rgb.size()));
    state.counters["file_MB"] = double(bytes) / 1e6;
}

BENCHMARK(BM_PngEncode8K)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PngEncode8KStb)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BvhBuild)->Arg(1000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PrimarySpheres1k)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PrimarySpheres1kPacket)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ShadowSpheres1k)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PrimaryGrid1M)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PrimaryGrid1MPacket)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ShadowGrid1M)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ShowcaseSpp)->ArgNames({"spp", "threads"})->Args({1, 1})->Args({1, 2})->Args({16, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Render1080p)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace whitted::bench

BENCHMARK_MAIN();
