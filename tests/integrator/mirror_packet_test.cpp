// A packet of camera rays traces its opaque mirrors' reflections together: every sample's colour
// and ray counts must be what the sample traced on its own gives (WhittedIntegrator::radiance for
// one ray finds its reflection itself), whatever the mirror (glossy, too faint to trace, glass
// that is no opaque mirror) and the depth limit.
#include <gtest/gtest.h>

#include "integrator/whitted_integrator.h"
#include "render/tile_renderer.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

Scene mirror_hall() {
    test::SceneBuilder b;
    Material floor, mirror, glossy, faint, glass, tinted;
    floor.diffuse = glm::vec3(0.4f);
    floor.reflect = glm::vec3(0.5f);
    mirror.diffuse = glm::vec3(0.05f);
    mirror.specular = glm::vec3(0.6f);
    mirror.shine = 80;
    mirror.reflect = glm::vec3(0.9f, 0.8f, 0.6f);
    glossy = mirror;
    glossy.gloss = 40.0f;
    faint = mirror;
    faint.reflect = glm::vec3(1.0f / 512.0f);  // below the weight worth a ray
    glass.diffuse = glm::vec3(0.1f);
    glass.reflect = glm::vec3(0.2f);
    glass.transparent = glm::vec3(0.7f);
    glass.ior = 1.5f;
    tinted = mirror;
    tinted.reflect = glm::vec3(0.0f, 0.0f, 0.3f);  // one channel only
    b.add(ShapeKind::Cube, test::translate_scale({0, -0.6f, -6}, {14, 0.2f, 14}), floor);
    const Material* kinds[] = {&mirror, &glossy, &faint, &glass, &tinted};
    for (int i = 0; i < 15; ++i) {
        const float x = float(i % 5) * 1.6f - 3.2f, z = -4.0f - float(i / 5) * 1.6f;
        b.add(ShapeKind(i % 4), test::translate_scale({x, 0.3f, z}, glm::vec3(1.1f)), *kinds[i % 5]);
    }
    b.light(test::point_light({3, 6, 2}, {0.8f, 0.8f, 0.8f}));
    b.light(test::point_light({-4, 4, 0}, {0.3f, 0.3f, 0.4f}));
    return b.build();
}

void expect_packets_match_single_rays(const Scene& scene, const Sampler& sampler, int max_depth) {
    SCOPED_TRACE("max depth " + std::to_string(max_depth) + ", " + std::to_string(sampler.samples_per_pixel()) +
                 " samples per pixel");
    const WhittedIntegrator integrator(scene, scene.data.camera, max_depth);
    const int width = 48, height = 36;
    RayCounts packet_counts, single_counts;
    int mismatches = 0;
    for (std::uint32_t index = 0; index < std::uint32_t(sampler.samples_per_pixel()); ++index)
        for (int y0 = 0; y0 < height; y0 += 4)
            for (int x0 = 0; x0 < width; x0 += 4) {
                CameraBatch batch;
                for (int l = 0; l < kPacketSize; ++l) {
                    const int x = x0 + l % 4, y = y0 + l / 4;
                    batch.rays[l] = camera_sample_ray(scene.data.camera, sampler, width, height, x, y, index);
                    batch.keys[l] = {std::uint32_t(x), std::uint32_t(y), index};
                }
                batch.active = 0xffffu & ~(1u << (x0 + y0) % kPacketSize);  // a lane left out, too
                glm::vec3 out[kPacketSize];
                integrator.radiance(batch, sampler, out, packet_counts);
                for (int l = 0; l < kPacketSize; ++l) {
                    if (!((batch.active >> l) & 1)) continue;
                    const glm::vec3 one = integrator.radiance(batch.rays[l], batch.keys[l], sampler, single_counts);
                    if (out[l] != one && ++mismatches <= 5)
                        ADD_FAILURE() << "pixel " << x0 + l % 4 << "," << y0 + l / 4 << " sample " << index << ": "
                                      << out[l].x << " " << out[l].y << " " << out[l].z << " in a packet, " << one.x
                                      << " " << one.y << " " << one.z << " alone";
                }
            }
    EXPECT_EQ(mismatches, 0);
    EXPECT_EQ(packet_counts.camera, single_counts.camera);
    EXPECT_EQ(packet_counts.reflected, single_counts.reflected);
    EXPECT_EQ(packet_counts.refracted, single_counts.refracted);
    EXPECT_EQ(packet_counts.shadow, single_counts.shadow);
    if (max_depth > 0) {
        EXPECT_GT(packet_counts.reflected, packet_counts.camera / 4) << "the mirrors fill the view";
    }
}

TEST(MirrorPackets, ChangeNoSampleAndNoRayCount) {
    const Scene scene = mirror_hall();
    for (int depth : {0, 1, 2, 5}) {
        expect_packets_match_single_rays(scene, Sampler(), depth);         // the pixel centres: gloss not drawn
        expect_packets_match_single_rays(scene, Sampler(2, 2, 3), depth);  // 8 samples: the glossy lobe drawn
    }
}

}  // namespace
}  // namespace whitted
