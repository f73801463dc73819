#pragma once
// Scenes for the micro-benchmarks, built in code (no parser): random transformed shapes and big
// grids of instances, plus the camera rays that look at them.
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "accel/bvh_packet.h"
#include "accel/scene.h"
#include "render/renderer.h"
#include "render/tile_renderer.h"

namespace whitted::bench {

inline Instance make_instance(ShapeKind kind, const glm::mat4& m, std::uint32_t material) {
    glm::dmat4 inv = glm::inverse(glm::dmat4(m));
    Instance inst{};
    for (int r = 0; r < 3; ++r)
        inst.world_to_object[r] = glm::vec4(float(inv[0][r]), float(inv[1][r]), float(inv[2][r]), float(inv[3][r]));
    inst.kind = kind;
    inst.material = material;
    return inst;
}

inline glm::mat4 random_affine(std::mt19937& rng, glm::vec3 centre, float size) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    glm::mat4 m = glm::translate(glm::mat4(1.0f), centre);
    glm::vec3 axis = glm::normalize(glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f) + 1e-3f);
    m = glm::rotate(m, 6.2831853f * u(rng), axis);
    return glm::scale(m, size * glm::vec3(0.4f + u(rng), 0.4f + u(rng), 0.4f + u(rng)));
}

// n randomly rotated, non-uniformly scaled spheres (or mixed shapes) inside a 20³ box around the
// origin, camera at z = 30 looking at the box.
inline SceneData random_scene(int n, bool mixed, std::uint32_t seed = 1) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-10.0f, 10.0f);
    SceneData flat;
    Material m;
    m.diffuse = glm::vec3(0.7f);
    flat.materials.push_back(m);
    const float size = 20.0f / std::cbrt(float(n)) * 1.2f;  // about one object per cell
    for (int i = 0; i < n; ++i) {
        ShapeKind kind = mixed ? ShapeKind(i % 4) : ShapeKind::Sphere;
        flat.instances.push_back(make_instance(kind, random_affine(rng, {pos(rng), pos(rng), pos(rng)}, size), 0));
    }
    flat.camera.eye = {0, 0, 30};
    flat.lights.push_back(Light{LightType::Point, {20, 40, 40}, {0, -1, 0}, glm::vec3(1.0f)});
    return flat;
}

// side² mixed shapes on a grid on the ground (y = 0), each randomly rotated and scaled in its
// cell, seen from above at an angle: the layout of the generator's big scenes.
inline SceneData grid_scene(int side, std::uint32_t seed = 1) {
    std::mt19937 rng(seed);
    SceneData flat;
    Material m;
    flat.materials.push_back(m);
    flat.instances.reserve(std::size_t(side) * side);
    for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) {
            glm::vec3 c(float(i) - 0.5f * side, 0.5f, float(j) - 0.5f * side);
            flat.instances.push_back(make_instance(ShapeKind((i + j) % 4), random_affine(rng, c, 0.6f), 0));
        }
    const float s = float(side);
    flat.camera.eye = {0, 0.35f * s, 0.75f * s};
    glm::vec3 target(0, 0, -0.1f * s);
    flat.camera.forward = glm::normalize(target - flat.camera.eye);
    flat.camera.right = glm::normalize(glm::cross(flat.camera.forward, glm::vec3(0, 1, 0)));
    flat.camera.up = glm::cross(flat.camera.right, flat.camera.forward);
    flat.lights.push_back(Light{LightType::Point, {0.3f * s, 2 * s, 0.4f * s}, {0, -1, 0}, glm::vec3(1.0f)});
    return flat;
}

// The camera rays of a width × height image in the order the renderer traces them: 32×32 tiles
// left to right, top to bottom, each row by row.
inline std::vector<Ray> camera_rays(const Camera& cam, int width, int height, int tile = 32) {
    std::vector<Ray> rays;
    rays.reserve(std::size_t(width) * height);
    for (int ty = 0; ty < height; ty += tile)
        for (int tx = 0; tx < width; tx += tile)
            for (int y = ty; y < std::min(ty + tile, height); ++y)
                for (int x = tx; x < std::min(tx + tile, width); ++x)
                    rays.push_back(cam.generate_ray(width, height, x + 0.5f, y + 0.5f, glm::vec2(0.5f)));
    return rays;
}

// The same camera rays as packets, in the order the renderer traces them: per 32×32 tile,
// blocks of kPacketWidth × kPacketHeight pixels row by row, lanes row-major in a block; blocks cut
// by the image's edge have their outside lanes inactive.
struct CameraPacket {
    Ray rays[kPacketSize];
    unsigned active = 0;
};
inline std::vector<CameraPacket> camera_packets(const Camera& cam, int width, int height, int tile = 32) {
    std::vector<CameraPacket> packets;
    for (int ty = 0; ty < height; ty += tile)
        for (int tx = 0; tx < width; tx += tile) {
            const int x1 = std::min(tx + tile, width), y1 = std::min(ty + tile, height);
            for (int by = ty; by < y1; by += kPacketHeight)
                for (int bx = tx; bx < x1; bx += kPacketWidth) {
                    CameraPacket p;
                    for (int l = 0; l < kPacketSize; ++l) {
                        const int x = bx + l % kPacketWidth, y = by + l / kPacketWidth;
                        if (x >= x1 || y >= y1) continue;
                        p.rays[l] = cam.generate_ray(width, height, x + 0.5f, y + 0.5f, glm::vec2(0.5f));
                        p.active |= 1u << l;
                    }
                    packets.push_back(p);
                }
        }
    return packets;
}

}  // namespace whitted::bench
