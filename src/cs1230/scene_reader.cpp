#include "cs1230/scene_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "base/transforms.h"
#include "cs1230/json_fields.h"
#include "cs1230/json_tree.h"
#include "parse/suggest.h"

namespace whitted::cs1230 {
namespace {

// The keys the course's reader accepts in each kind of object (and no others).
const std::vector<std::string_view> kRootKeys = {"name", "globalData", "cameraData", "groups", "templateGroups"};
const std::vector<std::string_view> kGlobalKeys = {"ambientCoeff", "diffuseCoeff", "specularCoeff", "transparentCoeff"};
const std::vector<std::string_view> kCameraKeys = {"position", "up", "heightAngle", "look", "focus", "aperture",
                                                   "focalLength"};
const std::vector<std::string_view> kGroupKeys = {"name", "translate", "rotate", "scale", "matrix",
                                                  "lights", "primitives", "groups"};
const std::vector<std::string_view> kLightKeys = {"type", "color", "name", "direction", "attenuationCoeff",
                                                  "angle", "penumbra"};
const std::vector<std::string_view> kPrimitiveKeys = {
    "type",   "meshFile",    "ambient",  "diffuse",  "specular", "reflective", "transparent", "shininess",
    "ior",    "blend",       "textureFile", "textureU", "textureV", "bumpMapFile", "bumpMapU", "bumpMapV"};

std::string in_quotes(std::string_view s) {
    std::string q = "'";  // appended: GCC 12 warns falsely (-Wrestrict) on "'" + std::string(…)
    q += s;
    q += '\'';
    return q;
}

glm::vec3 point_of(const glm::dmat4& m, const glm::vec3& p) { return glm::vec3(m * glm::dvec4(glm::dvec3(p), 1.0)); }
glm::vec3 direction_of(const glm::dmat4& m, const glm::vec3& d) { return glm::vec3(m * glm::dvec4(glm::dvec3(d), 0.0)); }

class SceneReader {
public:
    SceneReader(Context& ctx, SceneDescription& scene, const ReadOptions& options)
        : ctx_(ctx), scene_(scene), options_(options) {}

    void read(std::uint32_t root);

private:
    // A scope is the root or a template: a subgraph of the description. Its light events, in the
    // order a depth-first walk of the course's scene graph meets them: a light (placed in the
    // scope's frame) or a use of a template (under a matrix).
    struct LightEvent {
        int uses = -1;  // the template scope used; -1: `light`
        LightDesc light;
        glm::dmat4 matrix{1.0};
    };
    struct Scope {
        int subgraph = 0;
        std::vector<LightEvent> events;
        std::size_t lights = 0;  // after expanding its uses (saturating)
    };
    struct Template {
        int scope;
        std::uint32_t offset;  // of its `{`
    };

    void read_globals(std::uint32_t node);
    void read_camera(std::uint32_t node);
    void read_template(std::uint32_t node);
    void read_group(std::uint32_t node, int scope, const glm::dmat4& parent);
    void read_group_body(Fields& f, int scope, const glm::dmat4& parent);
    std::optional<glm::dmat4> group_matrix(Fields& f);
    std::optional<LightDesc> read_light(std::uint32_t node, const glm::dmat4& world);
    std::optional<ObjectDesc> read_primitive(std::uint32_t node);
    int add_scope(std::string name, std::uint32_t offset);
    void count_lights(int scope);
    void place_lights(std::uint32_t root_offset);

    Context& ctx_;
    SceneDescription& scene_;
    const ReadOptions& options_;
    float ka_ = 0, kd_ = 0, ks_ = 0, kt_ = 0;
    std::vector<Scope> scopes_;
    std::unordered_map<std::string, Template> templates_;  // name → the latest template of that name
    std::unordered_set<std::string> subgraph_names_;
    std::string defining_;  // the template being read ("" outside templateGroups)
    bool told_bump_maps_ = false;
};

void SceneReader::read(std::uint32_t root) {
    scene_.dialect = Dialect::Cs1230;
    scene_.lighting = LightingModel::Cs1230;
    Fields f(ctx_, root, "the scene file", kRootKeys);
    if (!f.ok()) return;
    f.check_keys();
    std::string name;
    f.string("name", name);  // the scene's name: checked, not used
    if (f.require("globalData")) read_globals(*f.node_of("globalData"));
    if (f.require("cameraData")) read_camera(*f.node_of("cameraData"));

    scene_.root = add_scope("", f.offset());  // the root is never named by a group: "" is free
    scene_.subgraphs[std::size_t(scene_.root)].loc = ctx_.at(f.offset());
    std::vector<std::uint32_t> items;
    if (f.array("templateGroups", items))
        for (std::uint32_t t : items) read_template(t);
    if (f.array("groups", items))
        for (std::uint32_t g : items) read_group(g, 0, glm::dmat4(1.0));
    count_lights(0);
    if (!has_errors(ctx_.diagnostics)) place_lights(f.offset());
}

void SceneReader::read_globals(std::uint32_t node) {
    Fields f(ctx_, node, "globalData", kGlobalKeys);
    f.check_keys();
    for (const char* key : {"ambientCoeff", "diffuseCoeff", "specularCoeff"}) f.require(key);
    f.number("ambientCoeff", ka_);
    f.number("diffuseCoeff", kd_);
    f.number("specularCoeff", ks_);
    f.number("transparentCoeff", kt_);
}

void SceneReader::read_camera(std::uint32_t node) {
    Fields f(ctx_, node, "cameraData", kCameraKeys);
    if (!f.ok()) return;
    f.check_keys();
    CameraDesc& cam = scene_.camera;
    cam.loc = ctx_.at(f.offset());
    for (const char* key : {"position", "up", "heightAngle"}) f.require(key);
    f.vec3("position", cam.eye);
    const bool up = f.vec3("up", cam.up);
    if (f.number("heightAngle", cam.angle_deg) && !(cam.angle_deg > 0.0f && cam.angle_deg < 180.0f))
        ctx_.error(f.get("heightAngle")->offset, "'heightAngle' in cameraData is the full vertical field of view in "
                                                 "degrees: it must lie between 0 and 180 (exclusive)");
    // Exactly one of look (a direction) and focus (a point), as the course's reader asks.
    const bool has_look = f.has("look"), has_focus = f.has("focus");
    bool view = false;
    if (has_look && has_focus) {
        const bool focus_later = f.key_offset("focus") > f.key_offset("look");
        ctx_.error(f.key_offset(focus_later ? "focus" : "look"),
                   "cameraData gives both 'look' (a direction) and 'focus' (a point): give one of them");
    } else if (has_look) {
        view = f.vec3("look", cam.look);
    } else if (has_focus) {
        view = f.vec3("focus", cam.focus);
        cam.use_focus = true;
    } else {
        ctx_.error(f.offset(), "cameraData has neither 'look' (a direction) nor 'focus' (a point looked at): "
                               "give one of them");
    }
    const char* view_key = cam.use_focus ? "focus" : "look";
    const glm::dvec3 dir(cam.view_direction());
    if (view && !(glm::length(dir) > 1e-12))
        ctx_.error(f.get(view_key)->offset, cam.use_focus ? "'focus' in cameraData equals 'position': there is no "
                                                            "view direction"
                                                          : "'look' in cameraData is zero: there is no view direction");
    if (up && !(glm::length(glm::dvec3(cam.up)) > 1e-12)) ctx_.error(f.get("up")->offset, "'up' in cameraData is zero");
    else if (up && view && glm::length(dir) > 1e-12 &&
             !(glm::length(glm::cross(glm::normalize(dir), glm::normalize(glm::dvec3(cam.up)))) > 1e-6))
        ctx_.error(f.get("up")->offset, "'up' in cameraData is parallel to the view direction");
    // Depth of field (the course's extra credit) on whitted's thin lens (§9.1).
    if (f.number("aperture", cam.aperture) && !(cam.aperture >= 0.0f))
        ctx_.error(f.get("aperture")->offset, "'aperture' in cameraData must be 0 or more");
    if (f.number("focalLength", cam.focal_distance) && !(cam.focal_distance > 0.0f))
        ctx_.error(f.get("focalLength")->offset, "'focalLength' in cameraData must be more than 0");
    if (cam.aperture > 0.0f && !f.has("focalLength") && has_look && !has_focus)
        ctx_.error(f.key_offset("aperture"), "a lens ('aperture' more than 0) needs 'focalLength' when the camera "
                                             "gives 'look': there is nothing to focus on");
}

int SceneReader::add_scope(std::string name, std::uint32_t offset) {
    // Subgraph names must be unique in a description; a second template of one name gets a suffix.
    std::string unique = name;
    for (int n = 2; !subgraph_names_.insert(unique).second; ++n) unique = name + "#" + std::to_string(n);
    SubgraphDesc sg;
    sg.name = unique;
    sg.loc = ctx_.at(offset);
    scene_.subgraphs.push_back(std::move(sg));
    Scope scope;
    scope.subgraph = int(scene_.subgraphs.size() - 1);
    scopes_.push_back(std::move(scope));
    return int(scopes_.size() - 1);
}

void SceneReader::read_template(std::uint32_t node) {
    Fields f(ctx_, node, "a template group", kGroupKeys);
    if (!f.ok()) return;
    std::string name;
    if (!f.require("name") || !f.string("name", name)) {
        f.check_keys();
        return;
    }
    const int scope = add_scope(name, f.offset());
    defining_ = name;
    read_group_body(f, scope, glm::dmat4(1.0));
    defining_.clear();
    count_lights(scope);
    if (auto it = templates_.find(name); it != templates_.end()) {
        const SourceLoc first = ctx_.at(it->second.offset);
        ctx_.warning(f.get("name")->offset, "a second template group named " + in_quotes(name) + " (the first is at " +
                                                std::to_string(first.line) + ":" + std::to_string(first.col) +
                                                "): the groups after it use this one, as in the course's reader");
    }
    templates_[name] = Template{scope, f.offset()};
}

void SceneReader::read_group(std::uint32_t node, int scope, const glm::dmat4& parent) {
    Fields f(ctx_, node, "a group", kGroupKeys);
    if (!f.ok()) return;
    std::string name;
    if (f.string("name", name)) {
        if (!defining_.empty() && name == defining_) {
            ctx_.error(f.get("name")->offset, "this group names " + in_quotes(name) + ", the template group it is in: "
                                              "a template can use only the templates defined before it");
            return;
        }
        if (auto it = templates_.find(name); it != templates_.end()) {
            // The course's reader takes such a group for the template and looks at nothing else in it.
            const auto others = f.members_except("name");
            if (!others.empty())
                ctx_.warning(others.front()->key_offset,
                             "this group names the template group " + in_quotes(name) + ": its other keys are ignored, "
                             "as in the course's reader");
            const Scope& used = scopes_[std::size_t(it->second.scope)];
            TransDesc t;
            t.matrix = glm::mat4(parent);
            t.loc = ctx_.at(f.offset());
            t.subgraphs.push_back({scene_.subgraphs[std::size_t(used.subgraph)].name, ctx_.at(f.get("name")->offset)});
            scene_.subgraphs[std::size_t(scopes_[std::size_t(scope)].subgraph)].children.push_back(std::move(t));
            LightEvent use;
            use.uses = it->second.scope;
            use.matrix = parent;
            scopes_[std::size_t(scope)].events.push_back(std::move(use));
            return;
        }
    }
    read_group_body(f, scope, parent);
}

std::optional<glm::dmat4> SceneReader::group_matrix(Fields& f) {
    // T · R · S · Matrix, whatever order the keys are written in (the course's reader).
    glm::dmat4 m(1.0);
    bool ok = true;
    glm::vec3 v;
    glm::vec4 r;
    glm::mat4 given;
    if (f.vec3("translate", v)) m = m * glm::dmat4(translation_matrix(v));
    if (f.vec4("rotate", r)) {
        if (auto rot = rotation_matrix(glm::vec3(r), r.w)) m = m * glm::dmat4(*rot);
        else ok = false, ctx_.error(f.get("rotate")->offset, "'rotate' in a group turns about a zero axis");
    }
    if (f.vec3("scale", v)) m = m * glm::dmat4(scale_matrix(v));
    if (f.matrix("matrix", given)) {
        if (given[0][3] != 0.0f || given[1][3] != 0.0f || given[2][3] != 0.0f || given[3][3] != 1.0f)
            ok = false, ctx_.error(f.get("matrix")->offset, "'matrix' in a group must be affine: its last row "
                                                            "must be 0 0 0 1 (a projective matrix cannot be drawn)");
        else
            m = m * glm::dmat4(given);
    }
    if (ok && is_singular(glm::mat4(m))) {
        ctx_.error(f.offset(), "this group's transforms are singular (a zero scale, or axes squeezed together): "
                               "nothing in it could be drawn");
        ok = false;
    }
    if (!ok) return std::nullopt;
    return m;
}

void SceneReader::read_group_body(Fields& f, int scope, const glm::dmat4& parent) {
    f.check_keys();
    const glm::dmat4 world = parent * group_matrix(f).value_or(glm::dmat4(1.0));
    std::vector<std::uint32_t> items;
    // The course's scene graph holds a group's lights before its children's.
    if (f.array("lights", items))
        for (std::uint32_t l : items)
            if (std::optional<LightDesc> light = read_light(l, world)) {
                LightEvent e;
                e.light = std::move(*light);
                scopes_[std::size_t(scope)].events.push_back(std::move(e));
            }
    if (f.array("primitives", items)) {
        TransDesc t;
        t.matrix = glm::mat4(world);
        t.loc = ctx_.at(f.offset());
        for (std::uint32_t p : items)
            if (std::optional<ObjectDesc> o = read_primitive(p)) t.objects.push_back(std::move(*o));
        if (!t.objects.empty())
            scene_.subgraphs[std::size_t(scopes_[std::size_t(scope)].subgraph)].children.push_back(std::move(t));
    }
    if (f.array("groups", items))
        for (std::uint32_t g : items) read_group(g, scope, world);
}

std::optional<LightDesc> SceneReader::read_light(std::uint32_t node, const glm::dmat4& world) {
    Fields f(ctx_, node, "a light", kLightKeys);
    if (!f.ok()) return std::nullopt;
    f.check_keys();
    f.require("type");
    f.require("color");
    LightDesc l;
    l.loc = ctx_.at(f.offset());
    bool ok = f.vec3("color", l.color);
    std::string type;
    if (!f.string("type", type)) return std::nullopt;
    std::vector<std::string_view> needs, uses;  // per type: required keys, and the keys it reads
    if (type == "directional") {
        l.type = LightType::Directional;
        needs = uses = {"direction"};
    } else if (type == "point") {
        l.type = LightType::Point;
        needs = uses = {"attenuationCoeff"};
    } else if (type == "spot") {
        l.type = LightType::Spot;
        needs = uses = {"direction", "attenuationCoeff", "angle", "penumbra"};
    } else {
        ctx_.error(f.get("type")->offset, "unknown light type " + in_quotes(type) + did_you_mean(type, "directional, point, spot") +
                                              ": a light is directional, point or spot");
        return std::nullopt;
    }
    for (std::string_view key : needs) ok = f.require(key) && ok;
    for (std::string_view key : {"direction", "attenuationCoeff", "angle", "penumbra"}) {
        bool used = false;
        for (std::string_view u : uses) used = used || u == key;
        if (!used && f.has(key))
            ctx_.warning(f.key_offset(key), in_quotes(key) + " has no effect on a " + type + " light");
    }
    glm::vec3 direction(0.0f, -1.0f, 0.0f);
    if (l.type != LightType::Point) {
        if (!f.vec3("direction", direction)) ok = false;
        else if (!(glm::length(direction) > 0.0f))
            ok = false, ctx_.error(f.get("direction")->offset, "'direction' of a light is zero");
    }
    if (l.type != LightType::Directional) ok = f.vec3("attenuationCoeff", l.falloff) && ok;
    if (l.type == LightType::Spot) {
        // Degrees: the outer cone's half-angle, and the band inside it where the light fades.
        // The course's renderer keeps the angle within [0, 90] and the band within [0, angle].
        float angle = 0, penumbra = 0;
        ok = f.number("angle", angle) && ok;
        ok = f.number("penumbra", penumbra) && ok;
        if (f.has("angle") && (angle < 0.0f || angle > 90.0f))
            ctx_.warning(f.get("angle")->offset, "'angle' of a spot light is taken within 0 to 90 degrees, as in the "
                                                 "course's renderer");
        angle = std::clamp(angle, 0.0f, 90.0f);
        if (f.has("penumbra") && (penumbra < 0.0f || penumbra > angle))
            ctx_.warning(f.get("penumbra")->offset, "'penumbra' of a spot light is taken within 0 and its 'angle', as "
                                                    "in the course's renderer");
        l.aperture_deg = angle;
        l.penumbra_deg = std::clamp(penumbra, 0.0f, angle);
    }
    if (!ok) return std::nullopt;
    l.position = point_of(world, glm::vec3(0.0f));
    l.direction = direction_of(world, direction);
    return l;
}

std::optional<ObjectDesc> SceneReader::read_primitive(std::uint32_t node) {
    Fields f(ctx_, node, "a primitive", kPrimitiveKeys);
    if (!f.ok()) return std::nullopt;
    f.check_keys();
    ObjectDesc o;
    o.loc = ctx_.at(f.offset());
    std::string type;
    if (!f.require("type") || !f.string("type", type)) return std::nullopt;
    if (type == "cube") o.kind = ShapeKind::Cube;
    else if (type == "sphere") o.kind = ShapeKind::Sphere;
    else if (type == "cylinder") o.kind = ShapeKind::Cylinder;
    else if (type == "cone") o.kind = ShapeKind::Cone;
    else if (type == "mesh") o.kind = ShapeKind::Mesh;
    else {
        ctx_.error(f.get("type")->offset, "unknown primitive type " + in_quotes(type) +
                                              did_you_mean(type, "cube, sphere, cylinder, cone, mesh") +
                                              ": a primitive is a cube, sphere, cylinder, cone or mesh");
        return std::nullopt;
    }
    bool ok = true;
    if (o.kind == ShapeKind::Mesh) {
        ok = f.require("meshFile") && f.string("meshFile", o.mesh_file);
        if (ok) o.mesh_loc = ctx_.at(f.get("meshFile")->offset);
    } else if (f.has("meshFile")) {
        ctx_.warning(f.key_offset("meshFile"), "'meshFile' has no effect on a " + type);
    }
    // The course's material: diffuse 1 1 1 by default, everything else 0.
    glm::vec3 oa(0.0f), od(1.0f), os(0.0f), orr(0.0f), ot(0.0f);
    float shininess = 0, ior = 0, blend = 0, repeat_u = 1, repeat_v = 1;
    for (auto [key, out] : {std::pair{"ambient", &oa}, {"diffuse", &od}, {"specular", &os}, {"reflective", &orr},
                            {"transparent", &ot}})
        if (f.has(key)) ok = f.vec3(key, *out) && ok;
    // Each number read once: a wrong one is one error. Where it must lie is checked after.
    auto number = [&](const char* key, float& out) {
        if (f.has(key) && !f.number(key, out)) ok = false;
        return f.has(key);
    };
    if (number("shininess", shininess) && shininess < 0.0f)
        ok = false, ctx_.error(f.get("shininess")->offset, "'shininess' must be 0 or more");
    number("ior", ior);
    if (number("blend", blend) && !(blend >= 0.0f && blend <= 1.0f))
        ok = false, ctx_.error(f.get("blend")->offset, "'blend' must lie between 0 and 1");
    for (auto [key, out] : {std::pair{"textureU", &repeat_u}, {"textureV", &repeat_v}})
        if (number(key, *out) && !(*out > 0.0f))
            ok = false, ctx_.error(f.get(key)->offset, in_quotes(key) + " (the times the texture repeats) must be more than 0");
    std::string texture;
    const bool textured = f.string("textureFile", texture);
    if (f.has("textureFile") && !textured) ok = false;
    if (!told_bump_maps_ && (f.has("bumpMapFile") || f.has("bumpMapU") || f.has("bumpMapV"))) {
        told_bump_maps_ = true;
        const char* key = f.has("bumpMapFile") ? "bumpMapFile" : f.has("bumpMapU") ? "bumpMapU" : "bumpMapV";
        ctx_.warning(f.key_offset(key), "bump maps are not drawn: 'bumpMapFile', 'bumpMapU' and 'bumpMapV' are "
                                        "ignored (in the whole file)");
    }
    if (!ok) return std::nullopt;

    // Folded with the global coefficients (§9.5).
    MaterialDesc& m = o.material;
    m.ambient = ka_ * oa;
    m.diffuse = kd_ * od;
    m.specular = shininess == 0.0f ? glm::vec3(0.0f) : ks_ * os;  // the course draws no highlight at n = 0
    m.shine = shininess;
    m.reflect = ks_ * orr;
    m.transparent = kt_ * ot;
    m.ior = ior > 0.0f ? ior : 1.0f;
    if (!(ior > 0.0f) && m.transparent != glm::vec3(0.0f)) {
        // The course's renderer refracts with 1/ior: with its default ior of 0 nothing comes through.
        ctx_.warning(f.has("ior") ? f.get("ior")->offset : f.key_offset("transparent"),
                     "a transparent primitive without an 'ior' above 0 lets nothing through, as in the course's "
                     "renderer (its ior defaults to 0)");
        m.transparent = glm::vec3(0.0f);
    }
    if (textured) {
        TextureRef ref;
        ref.file = texture;
        ref.repeat_u = repeat_u;
        ref.repeat_v = repeat_v;
        ref.loc = ctx_.at(f.get("textureFile")->offset);
        ref.allow_gif = true;
        m.texture = ref;
        m.blend = blend;
    }
    return o;
}

void SceneReader::count_lights(int scope) {
    constexpr std::size_t kMax = std::numeric_limits<std::size_t>::max();
    std::size_t n = 0;
    for (const LightEvent& e : scopes_[std::size_t(scope)].events) {
        const std::size_t add = e.uses < 0 ? 1 : scopes_[std::size_t(e.uses)].lights;
        n = n > kMax - add ? kMax : n + add;
    }
    scopes_[std::size_t(scope)].lights = n;
}

void SceneReader::place_lights(std::uint32_t root_offset) {
    if (scopes_[0].lights > options_.max_lights) {
        ctx_.error(root_offset, "the scene has " + std::to_string(scopes_[0].lights) +
                                    " lights once its templates are placed, more than the limit of " +
                                    std::to_string(options_.max_lights));
        return;
    }
    scene_.lights.reserve(scopes_[0].lights);
    // Depth first with an explicit stack: templates may nest as deep as there are templates.
    struct Frame {
        int scope;
        std::size_t next;
        glm::dmat4 matrix;
    };
    std::vector<Frame> stack{{0, 0, glm::dmat4(1.0)}};
    while (!stack.empty()) {
        Frame& top = stack.back();
        const std::vector<LightEvent>& events = scopes_[std::size_t(top.scope)].events;
        if (top.next == events.size()) {
            stack.pop_back();
            continue;
        }
        const LightEvent& e = events[top.next++];
        if (e.uses < 0) {
            LightDesc l = e.light;
            l.position = point_of(top.matrix, l.position);
            l.direction = direction_of(top.matrix, l.direction);
            scene_.lights.push_back(std::move(l));
        } else if (scopes_[std::size_t(e.uses)].lights > 0) {
            const glm::dmat4 m = top.matrix * e.matrix;  // before the push moves `top`
            stack.push_back({e.uses, 0, m});
        }
    }
}

}  // namespace

ParseResult read_scene(std::string_view text, const std::string& path, const ReadOptions& options) {
    ParseResult result;
    result.scene.path = path;
    result.scene.dialect = Dialect::Cs1230;
    // Textures and meshes are named relative to the parent of the file's folder (the course's
    // layout: scenefiles/illuminate/required/x.json names textures/earth.png in illuminate/).
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path file = fs::absolute(fs::path(path), ec);
    if (ec) file = fs::path(path);
    result.scene.asset_anchor = (file.parent_path().parent_path() / file.filename()).string();
    const LineIndex lines(text);
    JsonParseResult json = parse_json(text);
    Context ctx(json.tree, lines, path, result.diagnostics);
    ctx.lenient = options.lenient;
    if (!json.ok) {
        ctx.error(json.error_offset, "not valid JSON: " + json.error);
        return result;
    }
    SceneReader(ctx, result.scene, options).read(json.tree.root);
    ctx.finish();  // in file order, as for the bracket format (the reader visits keys in its own order)
    return result;
}

}  // namespace whitted::cs1230
