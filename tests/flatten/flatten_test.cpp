// Flattening the mastersubgraph graph: composition down the hierarchy (spec §3), instancing,
// materials shared between instances, and the camera basis (spec §5).
#include <cmath>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "accel/scene.h"
#include "accel/instance_geometry.h"
#include "flatten/flatten.h"
#include "integrator/light_sample.h"
#include "render/load_scene.h"

namespace whitted {
namespace {

glm::vec3 to_world(const Instance& inst, glm::vec3 p) { return glm::vec3(object_to_world(inst) * glm::vec4(p, 1.0f)); }

void expect_vec(glm::vec3 a, glm::vec3 b, float tol = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

TransDesc trans(glm::mat4 m) {
    TransDesc t;
    t.matrix = m;
    return t;
}

SceneDescription two_level_scene() {
    // root: trans [ translate 10 0 0  subgraph child ] and trans [ object sphere ]
    // child: trans [ scale 2 2 2  object cube ]
    SceneDescription d;
    d.path = "test.sc";
    SubgraphDesc root{"root", {}, {}};
    TransDesc a = trans(glm::translate(glm::mat4(1.0f), {10, 0, 0}));
    a.subgraphs.push_back({"child", {}});
    a.subgraphs.push_back({"child", {}});  // drawn twice: instancing
    TransDesc b = trans(glm::mat4(1.0f));
    b.objects.push_back({ShapeKind::Sphere, {}, {}});
    root.children = {a, b};
    SubgraphDesc child{"child", {}, {}};
    TransDesc c = trans(glm::scale(glm::mat4(1.0f), {2, 2, 2}));
    ObjectDesc cube{ShapeKind::Cube, {}, {}};
    cube.material.diffuse = {1, 0, 0};
    c.objects.push_back(cube);
    child.children = {c};
    d.subgraphs = {root, child};
    d.root = 0;
    return d;
}

TEST(Flatten, ComposesParentTimesChildDownTheHierarchy) {
    FlattenResult r = flatten(two_level_scene());
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.scene.instances.size(), 3u);
    int cubes = 0;
    for (const Instance& inst : r.scene.instances) {
        if (inst.kind != ShapeKind::Cube) continue;
        ++cubes;
        // world = T(10,0,0) · S(2): the corner (0.5, 0.5, 0.5) is scaled first, then moved.
        expect_vec(to_world(inst, {0.5f, 0.5f, 0.5f}), {11, 1, 1});
    }
    EXPECT_EQ(cubes, 2);
}

TEST(Flatten, InstancesOfOneObjectShareOneMaterial) {
    FlattenResult r = flatten(two_level_scene());
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.scene.materials.size(), 2u);  // the cube's and the sphere's
    std::uint32_t m = ~0u;
    for (const Instance& inst : r.scene.instances)
        if (inst.kind == ShapeKind::Cube) {
            if (m == ~0u) m = inst.material;
            EXPECT_EQ(inst.material, m);
        }
    EXPECT_EQ(r.scene.materials[m].diffuse, glm::vec3(1, 0, 0));
}

TEST(Flatten, RefusesInstancingThatExplodes) {
    // s0 uses s1 twice, s1 uses s2 twice, …: 2^40 objects from 40 tiny blocks.
    SceneDescription d;
    d.path = "boom.sc";
    for (int i = 0; i <= 40; ++i) {
        SubgraphDesc s{i == 0 ? "root" : "s" + std::to_string(i), {}, {}};
        TransDesc t = trans(glm::mat4(1.0f));
        if (i < 40) t.subgraphs = {{"s" + std::to_string(i + 1), {}}, {"s" + std::to_string(i + 1), {}}};
        else t.objects.push_back({ShapeKind::Sphere, {}, {}});
        s.children.push_back(t);
        d.subgraphs.push_back(s);
    }
    d.root = 0;
    FlattenResult r = flatten(d, {.max_instances = 1'000'000});
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.diagnostics[0].message.find("1099511627776"), std::string::npos) << r.diagnostics[0].message;
}

// 41 levels, each `trans [ subgraph s(i-1) subgraph s(i-1) ]`, over an s0 that draws nothing (issue
// 15, finding 2): 0 objects, so the object limit passes, and the walk used to visit all 2^41
// references (a day). A subgraph that draws nothing is never entered: the walk is root's one step
// plus its one trans block.
SceneDescription doubling_over_empty(int levels) {
    SceneDescription d;
    d.path = "empty_boom.sc";
    for (int i = 0; i <= levels; ++i) {
        SubgraphDesc s{i == levels ? "root" : "s" + std::to_string(i), {}, {}};
        TransDesc t = trans(glm::mat4(1.0f));
        if (i > 0) t.subgraphs = {{"s" + std::to_string(i - 1), {}}, {"s" + std::to_string(i - 1), {}}};
        s.children.push_back(t);
        d.subgraphs.push_back(s);
    }
    d.root = levels;
    return d;
}

TEST(Flatten, NeverEntersSubgraphsThatDrawNothing) {
    FlattenResult r = flatten(doubling_over_empty(41));
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.scene.instances.size(), 0u);
    EXPECT_EQ(r.steps, 2u);  // root itself and its one trans block
}

// A chain of 1,000 subgraphs down to one sphere, referenced 500 times from root: 500 objects
// (under a limit of 1,000) but 500 × (1,000 subgraphs + 1,000 trans blocks) + root's 2 = 1,000,002
// steps of walking. Refused from the counts, before any of it is walked.
TEST(Flatten, BoundsTheStepsOfTheWalkNotOnlyTheObjects) {
    SceneDescription d;
    d.path = "long.sc";
    constexpr int kChain = 1000, kRefs = 500;
    for (int i = 0; i < kChain; ++i) {
        SubgraphDesc s{"s" + std::to_string(i), {}, {}};
        TransDesc t = trans(glm::mat4(1.0f));
        if (i == 0) t.objects.push_back({ShapeKind::Sphere, {}, {}});
        else t.subgraphs = {{"s" + std::to_string(i - 1), {}}};
        s.children.push_back(t);
        d.subgraphs.push_back(s);
    }
    SubgraphDesc root{"root", {}, {}};
    TransDesc t = trans(glm::mat4(1.0f));
    for (int k = 0; k < kRefs; ++k) t.subgraphs.push_back({"s" + std::to_string(kChain - 1), {}});
    root.children.push_back(t);
    d.subgraphs.push_back(root);
    d.root = kChain;
    FlattenResult ok = flatten(d, {.max_instances = 1000, .max_steps = 1'000'002});
    ASSERT_TRUE(ok.ok());
    EXPECT_EQ(ok.scene.instances.size(), std::size_t(kRefs));
    EXPECT_EQ(ok.steps, 1'000'002u);
    FlattenResult refused = flatten(d, {.max_instances = 1000, .max_steps = 1'000'001});
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.diagnostics[0].message.find("1000002 steps"), std::string::npos) << refused.diagnostics[0].message;
    EXPECT_TRUE(refused.scene.instances.empty());
}

// 2^levels spheres: each level `trans [ subgraph s(i-1) subgraph s(i-1) ]` over one sphere.
SceneDescription doubling_over_sphere(int levels) {
    SceneDescription d = doubling_over_empty(levels);
    d.subgraphs[0].children[0].objects.push_back({ShapeKind::Sphere, {}, {}});
    return d;
}

// The memory a scene needs is estimated from the counts, before any object
// is made: 2^10 spheres at kBytesPerInstance (128) each is 131,072 bytes; the walk takes
// a(10) steps of kBytesPerStep (8) each, where a(0) = 2 (s0 and its trans block) and
// a(i) = 2 + 2·a(i − 1) (the subgraph, its trans block, two uses of the level below): a(10) =
// 2^12 − 2 = 4,094 steps, 32,752 bytes. In all 163,824 bytes (160.0 KiB).
TEST(Flatten, RefusesWhatExceedsTheMemoryLimitWithTheEstimate) {
    const SceneDescription d = doubling_over_sphere(10);
    static_assert(kBytesPerInstance == 128 && kBytesPerStep == 8);
    FlattenResult fits = flatten(d, {.max_bytes = 163'824});
    ASSERT_TRUE(fits.ok());
    EXPECT_EQ(fits.scene.instances.size(), 1024u);
    EXPECT_EQ(fits.steps, 4094u);
    FlattenResult refused = flatten(d, {.max_bytes = 163'823});
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(refused.scene.instances.empty());
    EXPECT_NE(refused.diagnostics[0].message.find("needs about 160.0 KiB of memory (1024 objects"), std::string::npos)
        << refused.diagnostics[0].message;
    EXPECT_NE(refused.diagnostics[0].message.find("and 4094 steps of expanding them, 8 bytes each"), std::string::npos)
        << refused.diagnostics[0].message;
    EXPECT_NE(refused.diagnostics[0].message.find("more than the limit of 160.0 KiB (--max-memory)"), std::string::npos)
        << refused.diagnostics[0].message;
}

TEST(Flatten, StopsWhenCancelled) {
    // 2^16 spheres: 65,536 references walked unless the walk looks at the flag.
    const SceneDescription d = doubling_over_sphere(16);
    const std::atomic<bool> cancel{true};
    FlattenResult r = flatten(d, {.cancel = &cancel});
    EXPECT_TRUE(r.cancelled);
    EXPECT_FALSE(r.ok());
    EXPECT_LT(r.scene.instances.size(), 65536u);
    EXPECT_EQ(flatten(d).scene.instances.size(), 65536u);
}

TEST(Flatten, AChainOfAHundredThousandSubgraphs) {
    // root -> s1 -> … -> s100000, each moving one step up x: one sphere at x = 100000. Counting
    // and expanding walk it without recursion (the call stack would not hold it under the
    // sanitizers) and find each name without a scan of all the others.
    constexpr int kDepth = 100'000;
    SceneDescription d;
    d.path = "chain.sc";
    auto name = [](int i) { return i == 0 ? std::string("root") : std::string("s").append(std::to_string(i)); };
    for (int i = 0; i <= kDepth; ++i) {
        SubgraphDesc s{name(i), {}, {}};
        TransDesc t = trans(i == 0 ? glm::mat4(1.0f) : glm::translate(glm::mat4(1.0f), {1, 0, 0}));
        if (i < kDepth) t.subgraphs = {{name(i + 1), {}}};
        else t.objects.push_back({ShapeKind::Sphere, {}, {}});
        s.children.push_back(t);
        d.subgraphs.push_back(s);
    }
    d.root = 0;
    FlattenResult r = flatten(d);
    ASSERT_TRUE(r.ok()) << r.diagnostics[0].message;
    ASSERT_EQ(r.scene.instances.size(), 1u);
    expect_vec(to_world(r.scene.instances[0], {0, 0, 0}), {float(kDepth), 0, 0});
}

TEST(Flatten, InverseTransposeBringsNormalsBack) {
    // Under scale (4, 1, 1) a sphere's normal at object point (0.5,0.5,0)/√2·… : take the object
    // normal (1,1,0)/√2; (M⁻¹)ᵀ scales x by 1/4, giving (1/4, 1, 0) normalised.
    SceneDescription d;
    d.path = "n.sc";
    SubgraphDesc root{"root", {}, {}};
    TransDesc t = trans(glm::scale(glm::mat4(1.0f), {4, 1, 1}));
    t.objects.push_back({ShapeKind::Sphere, {}, {}});
    root.children.push_back(t);
    d.subgraphs.push_back(root);
    d.root = 0;
    FlattenResult r = flatten(d);
    ASSERT_TRUE(r.ok());
    expect_vec(normal_to_world(r.scene.instances[0], glm::normalize(glm::vec3(1, 1, 0))),
               glm::normalize(glm::vec3(0.25f, 1, 0)));
}

TEST(Flatten, SpotlightFromTheFileLightsInsideItsApertureOnly) {
    // A spot 5 above the floor pointing down, half-angle 30°, exponent 0 (no fall-off inside):
    // a floor point at x = 5·tan θ is lit for θ = 29° and dark for θ = 31°. Direction written
    // unnormalised; colour 1, attenuation 1/(1 + 0·d + 0·d²).
    LoadResult r = load_scene_text(
        "light [ type spotlight position 0 5 0 direction 0 -3 0 aperture 30 exponent 0 color 1 1 1 ]\n"
        "mastersubgraph root [ trans [ object sphere [ ] ] ]\n",
        "spot.sc");
    ASSERT_TRUE(r.ok()) << r.diagnostics[0].str();
    const Light& spot = r.scene->data.lights.at(0);
    EXPECT_NEAR(spot.cos_aperture, std::cos(glm::radians(30.0f)), 1e-6f);
    expect_vec(spot.direction, {0, -1, 0});
    const float inside = 5.0f * std::tan(glm::radians(29.0f)), outside = 5.0f * std::tan(glm::radians(31.0f));
    expect_vec(sample_light(spot, {inside, 0, 0}).intensity, glm::vec3(1.0f));
    expect_vec(sample_light(spot, {outside, 0, 0}).intensity, glm::vec3(0.0f));
    // Exponent 2 inside the cone: cos²θ at 20°.
    r = load_scene_text("light [ type spotlight position 0 5 0 direction 0 -1 0 aperture 30 exponent 2 color 1 1 1 ]\n"
                        "mastersubgraph root [ trans [ object sphere [ ] ] ]\n",
                        "spot.sc");
    ASSERT_TRUE(r.ok());
    const float c20 = std::cos(glm::radians(20.0f));
    expect_vec(sample_light(r.scene->data.lights.at(0), {5.0f * std::tan(glm::radians(20.0f)), 0, 0}).intensity,
               glm::vec3(c20 * c20));
}

TEST(Camera, OrthonormalisesUpAndUsesFocus) {
    CameraDesc c;
    c.eye = {0, 0, 10};
    c.focus = {0, 0, 0};
    c.use_focus = true;
    c.up = {0, 1, 1};  // not perpendicular to the view
    c.angle_deg = 90;
    Camera cam = make_camera(c);
    expect_vec(cam.forward, {0, 0, -1});
    expect_vec(cam.up, {0, 1, 0});
    expect_vec(cam.right, {1, 0, 0});
    EXPECT_NEAR(cam.tan_half_fov, 1.0f, 1e-6f);
}

}  // namespace
}  // namespace whitted

namespace whitted {
namespace {

// One subgraph may hold a hundred thousand objects (or a million subgraphs one each): the walk
// looks at the cancel flag by the work done, not only between subgraphs.
TEST(Flatten, StopsWhenCancelledInsideOneBigSubgraph) {
    SceneDescription d;
    d.path = "flat.sc";
    SubgraphDesc root{"root", {}, {}};
    TransDesc t = trans(glm::mat4(1.0f));
    for (int i = 0; i < 100000; ++i) t.objects.push_back({ShapeKind::Sphere, {}, {}});
    root.children = {t};
    d.subgraphs = {root};
    d.root = 0;
    const std::atomic<bool> cancel{true};
    const FlattenResult r = flatten(d, {.cancel = &cancel});
    EXPECT_TRUE(r.cancelled);
    EXPECT_LT(r.scene.instances.size(), 100000u);
}

// The camera within the objects' range (10^30): at 3e38 every ray's arithmetic overflowed and the
// image came out black with exit 0. Within it, a camera far from what it looks at still gets its
// basis (float's |v|² overflows from 1.8e19 on: then it is found in double).
TEST(Flatten, TheCameraIsWithinTheRangeOfTheObjects) {
    SceneDescription d = two_level_scene();
    d.camera.eye = {3e38f, 0, 0};
    d.camera.loc = {"test.sc", 1, 1};
    FlattenResult r = flatten(d);
    ASSERT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_NE(r.diagnostics[0].message.find("the camera's eye is more than 1e30 from the origin"), std::string::npos)
        << r.diagnostics[0].message;
    d.camera.eye = {1e25f, 0, 0};
    d.camera.focus = {0, 0, 0};
    d.camera.use_focus = true;
    r = flatten(d);
    ASSERT_TRUE(r.ok());
    expect_vec(r.scene.camera.forward, {-1, 0, 0});
    expect_vec(r.scene.camera.right, glm::normalize(glm::cross(glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0))));
    EXPECT_FLOAT_EQ(r.scene.camera.focal_distance, 1e25f);
    // A camera that worked before is the same bits.
    d = two_level_scene();
    d.camera.eye = {1, 2, 3};
    d.camera.focus = {0.5f, -1, 0.25f};
    d.camera.use_focus = true;
    const Camera c = flatten(d).scene.camera;
    EXPECT_EQ(c.forward, glm::normalize(d.camera.focus - d.camera.eye));
}

}  // namespace
}  // namespace whitted
