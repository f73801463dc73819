// The packet query against the single-ray one: for every active lane exactly the same result
// (hit or not, t, instance, part) as intersect_nearest, whatever the packet holds — coherent
// camera rays, unrelated rays, lanes that miss everything, inactive lanes, ties, rays starting
// inside objects — and nothing written for the lanes that did not hit.
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "accel/bvh.h"
#include "accel/bvh_packet.h"
#include "accel/bvh_test_scenes.h"
#include "accel/instance_geometry.h"
#include "accel/walk_both_ways.h"

namespace whitted {
namespace {

using namespace test;
constexpr float kInf = std::numeric_limits<float>::infinity();

struct Packet {
    Ray rays[kPacketSize];
    unsigned active = ~0u >> (32 - kPacketSize);
};

// Traces the packet and each active lane alone; returns the number of lanes that hit.
int expect_same_as_single_rays(const Bvh& bvh, const std::vector<Instance>& instances, const Packet& p, float t_min,
                               float t_max, int packet_index) {
    // A sentinel in every lane: a lane that does not hit must be left untouched.
    const Hit sentinel{-7.0f, 0xdeadbeefu, kPartNegZ};
    Hit hits[kPacketSize];
    for (Hit& h : hits) h = sentinel;
    const unsigned got = intersect_nearest_packet(bvh, instances, p.rays, p.active, t_min, t_max, hits);
    EXPECT_EQ(got & ~p.active, 0u) << "packet " << packet_index << ": an inactive lane reported a hit";
    int hit_count = 0;
    for (int l = 0; l < kPacketSize; ++l) {
        if (!((p.active >> l) & 1)) {
            EXPECT_EQ(std::memcmp(&hits[l], &sentinel, sizeof(Hit)), 0) << "packet " << packet_index << " lane " << l;
            continue;
        }
        Hit want{};
        const bool hit = intersect_nearest(bvh, instances, p.rays[l], t_min, t_max, want);
        EXPECT_EQ(bool((got >> l) & 1), hit) << "packet " << packet_index << " lane " << l;
        if (!hit) {
            EXPECT_EQ(std::memcmp(&hits[l], &sentinel, sizeof(Hit)), 0) << "packet " << packet_index << " lane " << l;
            continue;
        }
        ++hit_count;
        EXPECT_EQ(hits[l].instance, want.instance) << "packet " << packet_index << " lane " << l;
        // Bitwise: the same float, not merely a close one.
        EXPECT_EQ(std::bit_cast<std::uint32_t>(hits[l].t), std::bit_cast<std::uint32_t>(want.t))
            << "packet " << packet_index << " lane " << l << ": " << hits[l].t << " vs " << want.t;
        EXPECT_EQ(hits[l].part, want.part) << "packet " << packet_index << " lane " << l;
    }
    return hit_count;
}

// Camera packets of 4 × (kPacketSize / 4) neighbouring pixels (as the renderer traces them) of a
// width × height view from `eye` toward `target`, vertical field of view 60°; at low resolutions
// the lanes of a packet diverge a lot.
std::vector<Packet> camera_packets(glm::vec3 eye, glm::vec3 target, int width, int height) {
    const glm::vec3 forward = glm::normalize(target - eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.001f, 1, 0)));
    const glm::vec3 up = glm::cross(right, forward);
    const float tan_half = 0.57735f, aspect = float(width) / float(height);
    std::vector<Packet> packets;
    constexpr int kW = 4, kH = kPacketSize / kW;
    for (int by = 0; by < height; by += kH)
        for (int bx = 0; bx < width; bx += kW) {
            Packet p;
            p.active = 0;
            for (int l = 0; l < kPacketSize; ++l) {
                const int x = bx + l % kW, y = by + l / kW;
                if (x >= width || y >= height) continue;  // the image's edge: lane off
                const float sx = (2.0f * (float(x) + 0.5f) / float(width) - 1.0f) * tan_half * aspect;
                const float sy = (1.0f - 2.0f * (float(y) + 0.5f) / float(height)) * tan_half;
                p.rays[l] = Ray{eye, glm::normalize(forward + sx * right + sy * up)};
                p.active |= 1u << l;
            }
            packets.push_back(p);
        }
    return packets;
}

// kPacketSize unrelated rays per packet.
std::vector<Packet> random_packets(const std::vector<Ray>& rays) {
    std::vector<Packet> packets;
    for (std::size_t i = 0; i + kPacketSize <= rays.size(); i += kPacketSize) {
        Packet p;
        for (int l = 0; l < kPacketSize; ++l) p.rays[l] = rays[i + l];
        packets.push_back(p);
    }
    return packets;
}

// Each test runs with the box tests in SSE (four lanes a step) and, where the CPU has it, AVX2
// (eight).
class BvhPacket : public WalkBothWays {};
INSTANTIATE_TEST_SUITE_P(BoxTest, BvhPacket, ::testing::Values(true, false), walk_name);

TEST_P(BvhPacket, CoherentCameraPacketsMatchSingleRays) {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        SCOPED_TRACE(seed);
        RandomScene scene = random_scene(seed, 300 + 100 * int(seed), 10.0f);
        Bvh bvh = build_bvh(scene.instances);
        // From outside the scene, from inside it (origins among the objects), and a view along an
        // axis (direction components of both signs and near zero within a packet).
        struct View { glm::vec3 eye, target; int w, h; };
        const View views[] = {{{0, 0, 30}, {0, 0, 0}, 64, 48},
                              {{3, -2, 1}, {-5, 4, 2}, 37, 23},  // odd size: partial packets
                              {{25, 0, 0}, {0, 0, 0}, 160, 120},
                              {{0, 0, 30}, {0, 0, 0}, 8, 6}};    // very coarse: lanes far apart
        int packets = 0, hits = 0, lanes = 0;
        for (const View& v : views)
            for (const Packet& p : camera_packets(v.eye, v.target, v.w, v.h)) {
                hits += expect_same_as_single_rays(bvh, scene.instances, p, 0.0f, kInf, packets++);
                lanes += std::popcount(p.active);
                if (HasFailure()) return;
            }
        EXPECT_GT(lanes, 20000);
        EXPECT_GT(hits, lanes / 4) << "the views should see many objects";
        EXPECT_LT(hits, lanes) << "and some background";
    }
}

TEST_P(BvhPacket, IncoherentPacketsMatchSingleRays) {
    for (std::uint32_t seed : {4u, 5u, 6u, 7u}) {
        SCOPED_TRACE(seed);
        RandomScene scene = random_scene(seed, 200 + 80 * int(seed), 10.0f);
        Bvh bvh = build_bvh(scene.instances);
        const std::vector<Packet> packets = random_packets(random_rays(seed, 8000, 10.0f, scene.instances));
        for (int i = 0; i < int(packets.size()); ++i) {
            expect_same_as_single_rays(bvh, scene.instances, packets[i], 0.0f, kInf, i);
            // Bounded segments, as secondary rays have.
            expect_same_as_single_rays(bvh, scene.instances, packets[i], 0.5f, 3.0f + float(i % 7), i);
            if (HasFailure()) return;
        }
    }
}

TEST_P(BvhPacket, ParallelRaysFromDifferentOrigins) {
    // Same direction, origins a small grid apart (an orthographic camera): the packet's
    // directions agree in sign, its origins differ; also directions with zero components.
    RandomScene scene = random_scene(10, 500, 10.0f);
    Bvh bvh = build_bvh(scene.instances);
    std::mt19937 rng(10);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int hits = 0, lanes = 0;
    for (int k = 0; k < 1500; ++k) {
        glm::vec3 dir = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
        if (k % 10 == 1) dir = {0, 0, -1};
        if (k % 10 == 2) dir = glm::normalize(glm::vec3(1, -1, 0));
        const glm::vec3 side = glm::normalize(glm::cross(dir, glm::vec3(0.3f, 1, 0.1f)));
        const glm::vec3 up = glm::cross(side, dir);
        const glm::vec3 start = 12.0f * glm::vec3(u(rng), u(rng), u(rng)) - 15.0f * dir;
        const float spacing = k % 3 == 0 ? 0.01f : 0.3f;
        Packet p;
        for (int l = 0; l < kPacketSize; ++l)
            p.rays[l] = Ray{start + spacing * (float(l % 4) * side + float(l / 4) * up), dir};
        hits += expect_same_as_single_rays(bvh, scene.instances, p, 0.0f, kInf, k);
        lanes += kPacketSize;
        if (HasFailure()) return;
    }
    EXPECT_GT(hits, lanes / 5);
}

TEST_P(BvhPacket, LanesMissingEverythingAndInactiveLanes) {
    RandomScene scene = random_scene(8, 400, 10.0f);
    Bvh bvh = build_bvh(scene.instances);
    std::vector<Ray> rays = random_rays(8, 8000, 10.0f, scene.instances);
    std::mt19937 rng(8);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<Packet> packets = random_packets(rays);
    int missing = 0;
    for (int i = 0; i < int(packets.size()); ++i) {
        Packet p = packets[i];
        p.active = unsigned(rng()) & (~0u >> (32 - kPacketSize));  // any subset, empty and full too
        for (int l = 0; l < kPacketSize; ++l) {
            if (!((p.active >> l) & 1)) {
                p.rays[l] = Ray{glm::vec3(nan), glm::vec3(nan)};  // never looked at
            } else if (rng() % 3 == 0) {
                // From far outside, pointing away from the scene: hits nothing.
                p.rays[l].origin = glm::vec3(100, 100, 100) * (1.0f + float(l));
                p.rays[l].direction = glm::normalize(glm::vec3(1, 0.5f + 0.1f * float(l), 0.7f));
                ++missing;
            }
        }
        expect_same_as_single_rays(bvh, scene.instances, p, 0.0f, kInf, i);
        if (HasFailure()) return;
    }
    EXPECT_GT(missing, 1000);
    // No lane active: nothing is traced, nothing written.
    Packet none = packets[0];
    none.active = 0;
    expect_same_as_single_rays(bvh, scene.instances, none, 0.0f, kInf, -1);
}

TEST_P(BvhPacket, TiesGoToTheLowestInstanceIndex) {
    // Identical instances: every hit is a tie among many; lanes from one origin and from many.
    std::vector<Instance> same;
    std::mt19937 rng(3);
    const glm::mat4 m = random_affine(rng, 1.0f);
    for (int i = 0; i < 1000; ++i) same.push_back(make_instance(m, ShapeKind(i % 4 == 3 ? 3 : 0), 0));
    // Two clusters of duplicates elsewhere, so that the tree has more than one kind of leaf.
    const glm::mat4 m2 = glm::translate(glm::mat4(1.0f), {4, 0, 0});
    for (int i = 0; i < 300; ++i) same.push_back(make_instance(m2, ShapeKind::Sphere, 0));
    Bvh bvh = build_bvh(same);
    int packets = 0, hits = 0;
    for (const Packet& p : camera_packets({0, 0, 12}, {2, 0, 0}, 40, 30))
        hits += expect_same_as_single_rays(bvh, same, p, 0.0f, kInf, packets++);
    for (const Packet& p : random_packets(random_rays(3, 2400, 3.0f, same)))
        hits += expect_same_as_single_rays(bvh, same, p, 0.0f, kInf, packets++);
    EXPECT_GT(hits, 500);
}

TEST_P(BvhPacket, RaysStartingInsideObjects) {
    RandomScene scene = random_scene(9, 500, 8.0f);
    Bvh bvh = build_bvh(scene.instances);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int packets = 0;
    for (int k = 0; k < 600; ++k) {
        // All lanes from the centre of one instance (a camera inside an object), or each lane
        // from the centre of another.
        Packet p;
        const bool shared = k % 2 == 0;
        const glm::vec3 centre(object_to_world(scene.instances[rng() % scene.instances.size()])[3]);
        for (int l = 0; l < kPacketSize; ++l) {
            p.rays[l].origin = shared ? centre : glm::vec3(object_to_world(scene.instances[rng() % scene.instances.size()])[3]);
            p.rays[l].direction = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + 1e-3f);
        }
        expect_same_as_single_rays(bvh, scene.instances, p, 0.0f, kInf, packets++);
        if (HasFailure()) return;
    }
}

TEST_P(BvhPacket, EmptyScene) {
    std::vector<Instance> none;
    Bvh bvh = build_bvh(none);
    Packet p;
    Hit hits[kPacketSize];
    EXPECT_EQ(intersect_nearest_packet(bvh, none, p.rays, p.active, 0.0f, kInf, hits), 0u);
}

TEST_P(BvhPacket, SingleInstance) {
    std::vector<Instance> one{make_instance(glm::mat4(1.0f), ShapeKind::Sphere, 0)};
    Bvh bvh = build_bvh(one);
    Packet p;
    for (int l = 0; l < kPacketSize; ++l) p.rays[l] = Ray{{0.15f * float(l), 0, 5}, {0, 0, -1}};
    Hit hits[kPacketSize];
    const unsigned got = intersect_nearest_packet(bvh, one, p.rays, p.active, 0.0f, kInf, hits);
    EXPECT_EQ(got, 0xfu) << "lanes 0-3 pass within the sphere's radius, 4-7 outside";
    for (const Packet& q : camera_packets({0, 0, 3}, {0, 0, 0}, 20, 20))
        expect_same_as_single_rays(bvh, one, q, 0.0f, kInf, 0);
}

}  // namespace
}  // namespace whitted
