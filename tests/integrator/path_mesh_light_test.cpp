// Emissive triangle meshes as area lights of the path tracer (scene-format.md §9.2, §9.3): sampled by
// world triangle area through the instance's matrix, weighed by MIS against the BSDF-sampled hits.
// Checked against independent answers: the view factor of a rectangle (closed form), the furnace
// inside a closed mesh, the area-weighted centroid of the world triangles, and the same emitter as
// an `object cube`. Tolerances come from the sample counts (standard errors of the samples).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "accel/instance_geometry.h"
#include "integrator/path_integrator.h"
#include "integrator/path_lights.h"
#include "integrator/path_test_support.h"
#include "mesh/uv_sphere.h"
#include "render/renderer.h"
#include "sampler/warp.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

using test::samples_of;
using test::Stats;
using test::stats_of;

// The unit square of the plane y = 0, two triangles.
TriangleMesh unit_quad() {
    TriangleMesh m;
    m.positions = {{-0.5f, 0, -0.5f}, {0.5f, 0, -0.5f}, {0.5f, 0, 0.5f}, {-0.5f, 0, 0.5f}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

// A closed UV sphere of radius 0.5 with flat normals (the furnace needs the BSDF's normal to be the
// surface's: a shading normal would send some samples out through the surface).
TriangleMesh flat_sphere() {
    return uv_sphere_mesh(16, 32, [](const glm::vec3&) { return 0.5f; });
}

Instance mesh_instance(const glm::mat4& m, std::uint32_t material, std::uint32_t mesh) {
    Instance inst = make_instance(m, ShapeKind::Mesh, material);
    inst.mesh = mesh;
    return inst;
}

// The view factor from a point to the rectangle [0, a] × [0, b] parallel to its plane at height h,
// the point under the corner (0, 0) (Howell's catalogue, configuration B-3); signed by a and b so
// that any rectangle is a sum of four of them.
double corner_view_factor(double a, double b, double h) {
    const double A = std::abs(a) / h, B = std::abs(b) / h;
    const double sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
    const double f = (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * kPi);
    return (a < 0) != (b < 0) ? -f : f;
}

// A Lambertian plane (albedo 1) under a rectangle of radiance L has radiance L · F (F the view
// factor). The rectangle is the mesh quad, scaled non-uniformly, turned about y and flipped upside
// down (emission is two-sided).
TEST(PathMeshLight, PlaneUnderAnEmissiveQuadHasTheViewFactorRadiance) {
    const float a = 1.6f, b = 0.7f, h = 1.5f, L = 2.0f, turn = 0.7f;
    const glm::mat4 m = glm::scale(glm::rotate(glm::rotate(glm::translate(glm::mat4(1.0f), {0, h, 0}), turn, {0, 1, 0}),
                                               kPi, {1, 0, 0}),
                                   {a, 1.0f, b});
    SceneData flat;
    Material plane;
    plane.diffuse = glm::vec3(1.0f);
    flat.materials = {plane, test::emitter(glm::vec3(L))};
    flat.instances.push_back(make_instance(test::translate_scale({0, -0.5f, 0}, {100, 1, 100}), ShapeKind::Cube, 0));
    flat.instances.push_back(mesh_instance(m, 1, 0));
    flat.meshes.push_back(unit_quad());
    flat.background = glm::vec3(0.0f);
    const Scene scene = accelerate(flat);
    const PathIntegrator path(scene, scene.data.camera, 1);
    for (const glm::vec2 p : {glm::vec2(0, 0), glm::vec2(0.3f, -0.2f), glm::vec2(1.2f, 0.5f), glm::vec2(-2.5f, 1.0f)}) {
        // The point in the rectangle's frame (turned back about y).
        const double c = std::cos(turn), s = std::sin(turn);
        const double x = c * p.x - s * p.y, z = s * p.x + c * p.y;
        const double x0 = -a / 2.0 - x, x1 = a / 2.0 - x, z0 = -b / 2.0 - z, z1 = b / 2.0 - z;
        const double F = corner_view_factor(x1, z1, h) - corner_view_factor(x0, z1, h) -
                         corner_view_factor(x1, z0, h) + corner_view_factor(x0, z0, h);
        const Stats st = stats_of(samples_of(path, Ray{{p.x, 0.5f, p.y}, {0, -1, 0}}, 2048));
        EXPECT_NEAR(st.mean, L * F, 4 * st.se + 1e-4) << "at " << p.x << ", " << p.y;
        EXPECT_GT(st.se, 0.0);
    }
}

// Inside a closed emitting, reflecting mesh the camera sees e / (1 − a) in every pixel.
TEST(PathMeshLight, FurnaceInsideAClosedMeshSeesEmitOverOneMinusAlbedo) {
    const float e = 0.4f, alb = 0.6f;
    Material m;
    m.diffuse = glm::vec3(alb);
    m.emit = glm::vec3(e);
    SceneData flat;
    flat.materials = {m};
    flat.instances.push_back(mesh_instance(test::translate_scale({0.3f, -0.2f, 0.1f}, {20.0f, 9.0f, 14.0f}), 0, 0));
    flat.meshes.push_back(flat_sphere());
    test::expect_furnace_image(accelerate(flat), e / (1 - alb));
}

// The light's points are spread by world area: their mean is the area-weighted centroid of the
// world triangles (computed here from the corners), the density 1 / world area, and from inside
// the closed mesh the density of directions integrates to 1.
TEST(PathMeshLight, SamplesAreUniformByWorldAreaUnderAnAffineMap) {
    const glm::mat4 m = glm::rotate(test::translate_scale({1, 2, 3}, {2.0f, 0.7f, 1.3f}), 0.6f,
                                    glm::normalize(glm::vec3(1, 2, 0.5f)));
    SceneData flat;
    flat.materials = {test::emitter(glm::vec3(1.0f))};
    flat.instances.push_back(mesh_instance(m, 0, 0));
    flat.meshes.push_back(flat_sphere());
    const Scene scene = accelerate(flat);
    const PathLights lights(scene);
    const TriangleMesh& mesh = scene.data.meshes[0];
    double area = 0;
    glm::dvec3 centroid(0.0);
    for (const TriangleIndices& t : mesh.triangles) {
        glm::dvec3 w[3];
        for (int k = 0; k < 3; ++k) w[k] = glm::dvec3(m * glm::vec4(mesh.positions[t[k]], 1.0f));
        const double a = 0.5 * glm::length(glm::cross(w[1] - w[0], w[2] - w[0]));
        area += a;
        centroid += a * (w[0] + w[1] + w[2]) / 3.0;
    }
    centroid /= area;
    EXPECT_NEAR(lights.pdf_area(0, glm::vec3(0.0f), glm::vec3(0.0f), {0, 1, 0}), 1.0 / area, 1e-5 / area);

    const int n = 20000;
    const Sampler sampler(1, n);
    std::vector<double> coords[3];
    for (int i = 0; i < n; ++i) {
        const SampleKey key{0, 0, std::uint32_t(i)};
        const AreaLightSample ls = lights.sample_area(0, glm::vec3(0.0f), sampler.get2d(key, 5), sampler.get2d(key, 6).x);
        EXPECT_FLOAT_EQ(ls.pdf_area, lights.pdf_area(0, glm::vec3(0.0f), ls.point, {0, 1, 0}));
        for (int k = 0; k < 3; ++k) coords[k].push_back(ls.point[k]);
    }
    for (int k = 0; k < 3; ++k) {
        const Stats s = stats_of(coords[k]);
        EXPECT_NEAR(s.mean, centroid[k], 4 * s.se + 1e-4) << "axis " << k;
    }

    const Instance& inst = scene.data.instances[0];
    const glm::vec3 inside = glm::vec3(m * glm::vec4(0, 0, 0, 1));
    std::vector<double> terms;
    for (int i = 0; i < n; ++i) {
        const glm::vec2 u = sampler.get2d({1, 0, std::uint32_t(i)}, 3);
        const glm::vec3 w = around_axis({0, 0, 1}, 1 - 2 * u.x, u.y);
        Hit hit;
        ASSERT_TRUE(scene.intersect(Ray{inside, w}, hit));
        const glm::vec3 n_obj = glm::normalize(triangle_geometric_normal(mesh, hit.triangle));
        const double pdf_w = lights.pdf_area(0, glm::vec3(0.0f), inside + hit.t * w, n_obj) * hit.t * hit.t / std::abs(glm::dot(normal_to_world(inst, n_obj), w));
        terms.push_back(4 * kPi * pdf_w);
    }
    const Stats s = stats_of(terms);
    EXPECT_NEAR(s.mean, 1.0, 4 * s.se + 1e-3);
}

// The same emitter as a 12-triangle mesh and as `object cube` (the same matrix) lights a floor
// alike: each pixel's mean radiance agrees within the two renders' standard errors.
TEST(PathMeshLight, EmissiveMeshCubeLightsTheFloorAsAnEmissiveObjectCube) {
    TriangleMesh cube;
    cube.positions = {{-.5f, -.5f, -.5f}, {.5f, -.5f, -.5f}, {.5f, .5f, -.5f}, {-.5f, .5f, -.5f},
                      {-.5f, -.5f, .5f},  {.5f, -.5f, .5f},  {.5f, .5f, .5f},  {-.5f, .5f, .5f}};
    cube.triangles = {{4, 5, 6}, {4, 6, 7}, {1, 0, 3}, {1, 3, 2}, {5, 1, 2}, {5, 2, 6},
                      {0, 4, 7}, {0, 7, 3}, {7, 6, 2}, {7, 2, 3}, {0, 1, 5}, {0, 5, 4}};
    const glm::mat4 m = glm::rotate(test::translate_scale({0.2f, 1.2f, -0.3f}, {1.4f, 0.3f, 0.6f}), 0.5f,
                                    glm::normalize(glm::vec3(0.3f, 1, 0.2f)));
    auto floor_radiance = [&](bool as_mesh) {
        SceneData flat;
        Material floor;
        floor.diffuse = glm::vec3(0.8f);
        flat.materials = {floor, test::emitter(glm::vec3(3.0f))};
        flat.instances.push_back(make_instance(test::translate_scale({0, -0.5f, 0}, {100, 1, 100}), ShapeKind::Cube, 0));
        if (as_mesh) {
            flat.instances.push_back(mesh_instance(m, 1, 0));
            flat.meshes.push_back(cube);
        } else {
            flat.instances.push_back(make_instance(m, ShapeKind::Cube, 1));
        }
        flat.background = glm::vec3(0.0f);
        const Scene scene = accelerate(flat);
        const PathIntegrator path(scene, scene.data.camera, 3);
        std::vector<Stats> out;
        for (float x : {0.0f, 0.7f, -1.1f, 2.0f})
            out.push_back(stats_of(samples_of(path, Ray{{x, 0.5f, 0.4f}, {0, -1, 0}}, 4096, as_mesh ? 1 : 2)));
        return out;
    };
    const std::vector<Stats> mesh = floor_radiance(true), cube_obj = floor_radiance(false);
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const double se = std::sqrt(mesh[i].se * mesh[i].se + cube_obj[i].se * cube_obj[i].se);
        EXPECT_NEAR(mesh[i].mean, cube_obj[i].mean, 4 * se + 1e-4) << "point " << i;
        EXPECT_GT(mesh[i].mean, 0.01);
    }
}

}  // namespace
}  // namespace whitted
