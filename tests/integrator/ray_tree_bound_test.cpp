// The rays of one camera sample are bounded: a mirror-and-glass scene doubles
// them at every level, and at --max-depth 38 one camera ray ran for minutes, deaf to Ctrl-C.
#include <cmath>

#include <gtest/gtest.h>

#include "integrator/shading_record.h"
#include "integrator/whitted_integrator.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

// The eye inside two nested spheres that reflect and transmit 90% (ior 1): every ray inside the
// outer one hits a sphere and splits in two, down to the depth limit (weights stay above 1/256
// for 52 levels); a ray leaving the outer one brings the white background.
Scene split_everywhere() {
    Material glass_mirror;
    glass_mirror.diffuse = glm::vec3(0.0f);
    glass_mirror.reflect = glm::vec3(0.9f);
    glass_mirror.transparent = glm::vec3(0.9f);
    glass_mirror.ior = 1.0f;
    test::SceneBuilder b;
    b.add(ShapeKind::Sphere, glm::scale(glm::mat4(1.0f), glm::vec3(4.0f)), glass_mirror)
        .add(ShapeKind::Sphere, glm::scale(glm::mat4(1.0f), glm::vec3(8.0f)), glass_mirror)
        .background(glm::vec3(1.0f));
    return b.build();
}

TEST(RayTreeBound, ACameraSampleTracesAtMostTheLimit) {
    const Scene scene = split_everywhere();
    const Ray ray{{0, 0, 0}, {0.3f, 0.2f, -1.0f}};
    auto rays_at = [&](int depth, glm::vec3* colour = nullptr) {
        RayCounts counts;
        const glm::vec3 c = WhittedIntegrator(scene, scene.data.camera, depth).radiance(ray, SampleKey{}, Sampler(), counts);
        if (colour) *colour = c;
        return counts.reflected + counts.refracted;
    };
    // The tree grows by about 1.6 a level (the rays leaving the outer sphere end): under the limit
    // at depth 12, every level adding rays; at depth 22 (some 50,000) cut at the limit, exactly.
    std::uint64_t before = 0;
    for (int depth = 1; depth <= 12; ++depth) {
        const std::uint64_t n = rays_at(depth);
        EXPECT_GT(n, before) << depth;
        EXPECT_LT(n, std::uint64_t(kMaxSecondaryRays)) << depth;
        before = n;
    }
    glm::vec3 c;
    EXPECT_EQ(rays_at(22, &c), std::uint64_t(kMaxSecondaryRays));
    EXPECT_TRUE(std::isfinite(c.x) && c.x > 0.0f);
    EXPECT_EQ(rays_at(38), std::uint64_t(kMaxSecondaryRays));  // (2^39 rays without the limit)
}

// The pixel inspector's record of a sample keeps the camera ray's hit and its rays' hits: a tree of
// a billion hits (--inspect at depth 30: 3.35 GB under --max-memory 512M) is not stored.
TEST(RayTreeBound, TheRecordKeepsTheHitsTheInspectorShows) {
    const Scene scene = split_everywhere();
    const Ray ray{{0, 0, 0}, {0.3f, 0.2f, -1.0f}};
    ShadingRecorder rec;
    RayCounts counts;
    const WhittedIntegrator whitted(scene, scene.data.camera, 16);
    const glm::vec3 recorded = whitted.radiance(ray, SampleKey{}, Sampler(), counts, rec);
    RayCounts plain_counts;
    EXPECT_EQ(recorded, whitted.radiance(ray, SampleKey{}, Sampler(), plain_counts));  // the same shading
    // The camera ray's hit, its reflected and its refracted ray's, and deeper ones up to the bound
    // (this tree splits at every hit: 2^16 hits unbounded; the camera sample's ray limit stops it first).
    ASSERT_GE(rec.nodes.size(), 3u);
    EXPECT_LE(rec.nodes.size(), ShadingRecorder::kMaxNodes);
    EXPECT_EQ(rec.nodes[0].depth, 0);
    EXPECT_EQ(rec.nodes[0].reflect.outcome, SecondaryRecord::Outcome::Traced);
    EXPECT_EQ(rec.nodes[0].refract.outcome, SecondaryRecord::Outcome::Traced);
    for (int k : {rec.nodes[0].reflect.node, rec.nodes[0].refract.node}) {
        ASSERT_GT(k, 0);
        EXPECT_EQ(rec.nodes[std::size_t(k)].depth, 1);
    }
    // What the reflected ray brought back is the whole subtree's colour.
    const SecondaryRecord& r = rec.nodes[0].reflect;
    EXPECT_GT(r.color.x, 0.0f);
}

}  // namespace
}  // namespace whitted
