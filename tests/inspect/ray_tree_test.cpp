// The ray tree of a pixel: every segment of scenes whose rays are known by hand (a mirror and a glass
// sphere; a glass prism with total internal reflection; a shadow on the floor), its projection
// into the image, and its export.
#include <sstream>

#include <gtest/gtest.h>

#include "inspect/inspect_scene.h"
#include "inspect/pixel_inspector.h"
#include "inspect/ray_tree_scene.h"
#include "render/load_scene.h"

namespace whitted {
namespace {

std::shared_ptr<const Scene> load(const std::string& text, const std::string& name) {
    LoadResult r = load_scene_text(text, name);
    EXPECT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].str());
    return r.scene;
}

void expect_near(const glm::vec3& got, const glm::vec3& want, float eps, const char* what) {
    EXPECT_NEAR(got.x, want.x, eps) << what;
    EXPECT_NEAR(got.y, want.y, eps) << what;
    EXPECT_NEAR(got.z, want.z, eps) << what;
}

RayTree mirror_and_glass_tree() {
    const auto scene = load(test::kRayTreeScene, "tree.sc");
    RenderJob job;
    job.width = test::kRayTreeWidth;
    job.height = test::kRayTreeHeight;
    return scene ? inspect_pixel(*scene, job, test::kRayTreeX, test::kRayTreeY).ray_tree : RayTree{};
}

TEST(RayTree, MirrorAndGlassSphereGiveTheSegmentsWorkedOutByHand) {
    const RayTree tree = mirror_and_glass_tree();
    ASSERT_EQ(tree.segments.size(), 7u) << ray_tree_text(tree, "");
    const auto& s = tree.segments;
    const float eps = 1e-3f;  // the secondary rays start a hair off their surface
    // 0: the camera ray, to the mirror.
    EXPECT_EQ(s[0].kind, RayKind::Camera);
    EXPECT_EQ(s[0].depth, 0);
    expect_near(s[0].from, {0, 0, 10}, 1e-6f, "eye");
    expect_near(s[0].to, test::kMirrorHit, 1e-5f, "mirror hit");
    EXPECT_TRUE(s[0].hit);
    EXPECT_EQ(s[0].shape, ShapeKind::Cube);
    EXPECT_EQ(s[0].object.line, 7);
    // 1: the mirror point's shadow ray reaches the light (nothing between).
    EXPECT_EQ(s[1].kind, RayKind::Shadow);
    EXPECT_EQ(s[1].depth, 0);
    EXPECT_EQ(s[1].parent, 0);
    EXPECT_EQ(s[1].shadow, ShadowState::Lit);
    expect_near(s[1].to, test::kRayTreeLight, 1e-6f, "light");
    // 2: reflected to +x, into the sphere.
    EXPECT_EQ(s[2].kind, RayKind::Reflected);
    EXPECT_EQ(s[2].depth, 1);
    EXPECT_EQ(s[2].parent, 0);
    expect_near(s[2].from, test::kMirrorHit, eps, "reflected from");
    expect_near(s[2].to, test::kGlassEntry, eps, "glass entry");
    EXPECT_EQ(s[2].shape, ShapeKind::Sphere);
    EXPECT_FALSE(s[2].inside);
    // 3: the entry point is lit too.
    EXPECT_EQ(s[3].kind, RayKind::Shadow);
    EXPECT_EQ(s[3].parent, 2);
    EXPECT_EQ(s[3].shadow, ShadowState::Lit);
    // 4: refracted head on through the sphere.
    EXPECT_EQ(s[4].kind, RayKind::Refracted);
    EXPECT_EQ(s[4].depth, 2);
    EXPECT_EQ(s[4].parent, 2);
    EXPECT_TRUE(s[4].inside);
    expect_near(s[4].to, test::kGlassExit, eps, "glass exit");
    // 5: from inside, the light is seen through the sphere's own glass: tinted by its 0.9.
    EXPECT_EQ(s[5].kind, RayKind::Shadow);
    EXPECT_EQ(s[5].parent, 4);
    EXPECT_EQ(s[5].shadow, ShadowState::Tinted);
    expect_near(s[5].tint, glm::vec3(0.9f), 1e-6f, "tint");
    // 6: out of the sphere, on along +x, out of the scene.
    EXPECT_EQ(s[6].kind, RayKind::Refracted);
    EXPECT_EQ(s[6].depth, 3);
    EXPECT_EQ(s[6].parent, 4);
    EXPECT_FALSE(s[6].inside);
    EXPECT_TRUE(s[6].escaped);
    EXPECT_GT(s[6].to.x, 4.0f);
    expect_near(glm::normalize(s[6].to - s[6].from), {1, 0, 0}, 1e-4f, "leaves along +x");
    EXPECT_EQ(tree.deepest(), 3);
}

// A glass prism (a cube turned 45° about y) seen off its axis: the ray entering its front-right
// face at 45° bends by Snell's law and meets the back-right face beyond the critical angle.
TEST(RayTree, TotalInternalReflectionIsMarkedWhereItHappens) {
    const std::string text = "camera [ eye 1 0 10 focus 1 0 0 angle 30 ]\n"
                             "light [ position 0 8 8 ]\n"
                             "mastersubgraph root [ trans [ rotate 0 1 0 45 scale 2 2 2\n"
                             "  object cube [ diffuse 0 0 0 transparent 0.9 0.9 0.9 ior 1.5 ] ] ]\n";
    const auto scene = load(text, "prism.sc");
    ASSERT_TRUE(scene);
    RenderJob job;
    job.width = job.height = 9;  // pixel 4, 4: the ray along -z at x = 1
    const RayTree tree = inspect_pixel(*scene, job, 4, 4).ray_tree;
    // By hand: the prism's faces are x ± z = ±√2. Entering x + z = √2 at x = 1 with normal
    // n = (1, 0, 1)/√2, cos i = 1/√2, η = 1/1.5: t = η·d + (η·cos i − cos t)·n.
    const float a = std::sqrt(2.0f), eta = 1.0f / 1.5f, cos_i = 1.0f / a;
    const float cos_t = std::sqrt(1.0f - eta * eta * (1.0f - cos_i * cos_i));
    const glm::vec3 n = glm::vec3(1, 0, 1) / a, d = eta * glm::vec3(0, 0, -1) + (eta * cos_i - cos_t) * n;
    const glm::vec3 entry{1, 0, a - 1};
    // Where it meets x − z = √2, and the angle there with that face's normal (1, 0, -1)/√2.
    const float k = (a - (entry.x - entry.z)) / (d.x - d.z);
    const glm::vec3 tir_point = entry + k * d;
    ASSERT_GT(glm::dot(d, glm::vec3(1, 0, -1) / a), 0.0f);
    ASSERT_LT(glm::dot(d, glm::vec3(1, 0, -1) / a), std::sqrt(1.0f - 1.0f / (1.5f * 1.5f)))
        << "beyond the critical angle (cos below cos 41.8°)";
    const RaySegment* inside = nullptr;
    const RaySegment* tir = nullptr;
    for (const RaySegment& s : tree.segments) {
        if (s.kind == RayKind::Refracted && s.depth == 1) inside = &s;
        if (s.total_internal_reflection && !tir) tir = &s;
    }
    ASSERT_TRUE(inside) << ray_tree_text(tree, "");
    EXPECT_TRUE(inside->inside);
    expect_near(inside->to, tir_point, 1e-3f, "the point of total internal reflection");
    ASSERT_TRUE(tir) << ray_tree_text(tree, "");
    EXPECT_EQ(tir->kind, RayKind::Reflected);
    EXPECT_EQ(tir->depth, 2);
    EXPECT_TRUE(tir->inside);
    expect_near(tir->from, tir_point, 1e-3f, "TIR ray from");
    expect_near(glm::normalize(tir->to - tir->from), glm::reflect(d, -glm::vec3(1, 0, -1) / a), 1e-4f, "mirror direction");
    EXPECT_NE(ray_tree_text(tree, "").find("reflected depth 2, after"), std::string::npos);
    EXPECT_NE(ray_tree_text(tree, "").find("(total internal reflection)"), std::string::npos);
}

// The floor point under the inspector scene's sphere: its shadow ray ends on the sphere's underside.
TEST(RayTree, ABlockedShadowRayEndsOnWhatBlocksIt) {
    const auto scene = load(test::kInspectScene, "inspect.sc");
    ASSERT_TRUE(scene);
    RenderJob job;
    job.width = test::kInspectWidth;
    job.height = test::kInspectHeight;
    const glm::ivec2 p = test::project(test::kFloorInShadow);
    const RayTree tree = inspect_pixel(*scene, job, p.x, p.y).ray_tree;
    ASSERT_GE(tree.segments.size(), 2u);
    const RaySegment& shadow = tree.segments[1];
    ASSERT_EQ(shadow.kind, RayKind::Shadow) << ray_tree_text(tree, "");
    EXPECT_EQ(shadow.shadow, ShadowState::Blocked);
    EXPECT_EQ(shadow.shape, ShapeKind::Sphere);
    // On the sphere (centre (0, 2, 0), radius 0.5), on the line from the floor point to the light (0, 10, 0).
    EXPECT_NEAR(glm::length(shadow.to - glm::vec3(0, 2, 0)), 0.5f, 1e-3f);
    const glm::vec3 along = glm::normalize(glm::vec3(0, 10, 0) - shadow.from);
    EXPECT_NEAR(glm::length(glm::cross(shadow.to - shadow.from, along)), 0.0f, 1e-3f);
    EXPECT_LT(shadow.to.y, 2.0f) << "its underside";
}

TEST(RayTree, ProjectionIsThePinholesClosedForm) {
    const RayTree tree = mirror_and_glass_tree();
    for (const glm::vec3& p : {test::kMirrorHit, test::kGlassEntry, test::kGlassExit, glm::vec3(-3, 2, -5)}) {
        const auto got = project_point(tree.camera, tree.width, tree.height, p);
        ASSERT_TRUE(got);
        const glm::vec2 want = test::ray_tree_project(p);
        EXPECT_NEAR(got->x, want.x, 1e-3f);
        EXPECT_NEAR(got->y, want.y, 1e-3f);
    }
    EXPECT_FALSE(project_point(tree.camera, tree.width, tree.height, {0, 0, 11}));  // behind the eye
    // The camera ray lands on its pixel's centre.
    const auto cam = project_segment(tree.camera, tree.width, tree.height, tree.segments[0].from, tree.segments[0].to);
    ASSERT_TRUE(cam);
    EXPECT_NEAR(cam->a.x, 100.5f, 1e-3f);
    EXPECT_NEAR(cam->a.y, 75.5f, 1e-3f);
    EXPECT_NEAR(cam->b.x, 100.5f, 1e-3f);
    // A segment from in front of the camera to behind it is cut where it leaves the image.
    const auto cut = project_segment(tree.camera, tree.width, tree.height, {0, 0, 0}, {20, 0, 20});
    ASSERT_TRUE(cut);
    EXPECT_NEAR(cut->a.x, 100.5f, 1e-3f);
    EXPECT_NEAR(cut->b.x, float(tree.width), 1e-3f);
    EXPECT_NEAR(cut->b.y, 75.5f, 1e-3f);
    // Outside the picture altogether.
    EXPECT_FALSE(project_segment(tree.camera, tree.width, tree.height, {-50, 40, 0}, {-60, 40, 0}));
}

TEST(RayTree, ExportsAsObjPolylinesAndJson) {
    const RayTree tree = mirror_and_glass_tree();
    const std::string obj = ray_tree_obj(tree, "pixel 100,75 of tree.sc");
    std::istringstream in(obj);
    std::vector<glm::vec3> v;
    std::vector<std::pair<int, int>> lines;
    std::vector<std::string> names;
    for (std::string line; std::getline(in, line);) {
        std::istringstream ls(line);
        std::string tag;
        ls >> tag;
        if (tag == "v") {
            glm::vec3 p;
            ls >> p.x >> p.y >> p.z;
            v.push_back(p);
        } else if (tag == "l") {
            int a = 0, b = 0;
            ls >> a >> b;
            lines.emplace_back(a, b);
        } else if (tag == "o") {
            std::string name;
            ls >> name;
            names.push_back(name);
        }
    }
    ASSERT_EQ(lines.size(), tree.segments.size());
    ASSERT_EQ(names.size(), tree.segments.size());
    EXPECT_EQ(names[2], "2_reflected_depth1");
    for (std::size_t i = 0; i < lines.size(); ++i) {
        ASSERT_GE(lines[i].first, 1);
        ASSERT_LE(lines[i].second, int(v.size()));
        EXPECT_EQ(v[std::size_t(lines[i].first - 1)], tree.segments[i].from);  // %.9g reads back exactly
        EXPECT_EQ(v[std::size_t(lines[i].second - 1)], tree.segments[i].to);
    }
    const std::string json = ray_tree_json(tree, 100, 75, "");
    EXPECT_EQ(json.rfind("{\"pixel\":[100,75],\"image\":[201,151],\"camera\":{\"eye\":[0,0,10],", 0), 0u) << json;
    EXPECT_NE(json.find("\"kind\":\"shadow\",\"depth\":2,\"parent\":4"), std::string::npos) << json;
    EXPECT_NE(json.find("\"shadow\":\"tinted\",\"tint\":[0.899999976,0.899999976,0.899999976]"), std::string::npos)
        << json;
    EXPECT_NE(json.find("\"object\":\"tree.sc:7:5\",\"shape\":\"cube\""), std::string::npos) << json;
}

}  // namespace
}  // namespace whitted
