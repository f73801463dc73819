#include "parse/parser.h"

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>
#include <utility>

#include "parse/falloff.h"
#include "parse/lexer.h"
#include "parse/number.h"
#include "parse/scene_checks.h"
#include "parse/transforms.h"

namespace whitted {
namespace {

// Thrown after the first error has been recorded; caught in parse_scene_text. One good error is
// more useful than a cascade, and unwinding keeps the recursive-descent code straight.
struct ParseStop {};

// The keywords each block accepts, for "expected one of" hints.
constexpr const char* kTopKeywords = "background, camera, light, mastersubgraph";
constexpr const char* kBackgroundKeywords = "color";
constexpr const char* kCameraKeywords = "eye, look, focus, up, angle, near-far, aperture, focaldistance";
constexpr const char* kLightKeywords =
    "type, position, direction, color, function, aperture, exponent, radius, angle, ambient";
constexpr const char* kSubgraphKeywords = "trans";
constexpr const char* kTransKeywords =
    "translate, scale, rotate, matrixRC, matrixCR, object, subgraph";
constexpr const char* kObjectKeywords =
    "ambient, diffuse, specular, reflect, transparent, emit, shine, ior, gloss, texture, file";
constexpr const char* kShapeNames = "cube, cylinder, cone, sphere, mesh";

// A token as it should appear in a message: quoted, printable, not absurdly long.
std::string describe(const Token& t) {
    switch (t.kind) {
        case TokenKind::End: return "end of file";
        case TokenKind::Open: return "'['";
        case TokenKind::Close: return "']'";
        case TokenKind::Word: break;
    }
    std::string s = "'";
    const size_t limit = 40;
    for (size_t i = 0; i < t.text.size() && i < limit; ++i) {
        const unsigned char c = static_cast<unsigned char>(t.text[i]);
        if (c >= 0x20 && c < 0x7f) {
            s += static_cast<char>(c);
        } else {
            static const char* hex = "0123456789abcdef";
            s += "\\x";
            s += hex[c >> 4];
            s += hex[c & 15];
        }
    }
    if (t.text.size() > limit) s += "...";
    return s + "'";
}

std::string pos_str(const Token& t) { return std::to_string(t.line) + ":" + std::to_string(t.col); }

std::string num_str(float v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

class Parser {
public:
    Parser(std::string_view text, const std::string& file, const ParseOptions& options)
        : tokens_(tokenize(text)), file_(file), options_(options) {
        scene_.path = file;
    }

    ParseResult run() {
        ParseResult result;
        try {
            parse_file();
            check_whole_file();
            result.scene = std::move(scene_);
        } catch (const ParseStop&) {
            // The error is already in diags_.
        }
        result.diagnostics = std::move(diags_);
        return result;
    }

private:
    std::vector<Token> tokens_;
    size_t pos_ = 0;
    const std::string& file_;
    ParseOptions options_;
    std::vector<Diagnostic> diags_;
    SceneDescription scene_;
    SourceLoc camera_up_loc_, camera_view_loc_, camera_aperture_loc_;  // line 0 until written
    std::unordered_map<std::string, int> subgraph_index_;  // for duplicates, without O(n²)

    // ---- tokens and diagnostics -------------------------------------------------------------

    const Token& peek() const { return tokens_[pos_]; }
    const Token& next() {
        const Token& t = tokens_[pos_];
        if (t.kind != TokenKind::End) ++pos_;  // End repeats forever: no reading past the end
        return t;
    }
    SourceLoc loc(const Token& t) const { return {file_, t.line, t.col}; }

    [[noreturn]] void fail(const SourceLoc& at, std::string message) {
        diags_.push_back({Severity::Error, at, std::move(message)});
        throw ParseStop{};
    }
    [[noreturn]] void fail(const Token& at, std::string message) {
        fail(loc(at), std::move(message));
    }
    void warn(const SourceLoc& at, std::string message) {
        diags_.push_back({Severity::Warning, at, std::move(message)});
    }

    // A '[' that opens no block: the reference ignores it wherever it appears (spec §1), so we do
    // too, with a warning, since it often means the brackets around it do not match.
    void skip_stray_opens(const std::string& where) {
        while (peek().kind == TokenKind::Open)
            warn(loc(next()), "'[' " + where + " opens no block and is ignored ('[' belongs after "
                              "a block keyword such as 'trans' or 'object TYPE')");
    }

    [[noreturn]] void fail_unclosed(const Token& opener, const std::string& block) {
        fail(peek(), "unexpected end of file: " + block + " block opened at " + pos_str(opener) +
                         " is not closed (missing ']')");
    }

    // ---- values -----------------------------------------------------------------------------

    float number(const Token& keyword) {
        skip_stray_opens("among the numbers of '" + std::string(keyword.text) + "'");
        const Token& t = peek();
        const std::string what =
            "expected a number for '" + std::string(keyword.text) + "', found ";
        if (t.kind != TokenKind::Word) fail(t, what + describe(t));
        const NumberParse n = parse_number(t.text);
        switch (n.status) {
            case NumberStatus::Invalid: fail(t, what + describe(t));
            case NumberStatus::OutOfRange:
                fail(t, "number " + describe(t) + " for '" + std::string(keyword.text) +
                            "' is out of range");
            case NumberStatus::TrailingComma:
                warn(loc(t), "trailing ',' after number " + describe(t) + " ignored");
                break;
            case NumberStatus::Ok: break;
        }
        next();
        return n.value;
    }

    glm::vec3 vec3(const Token& keyword) {
        const float x = number(keyword);
        const float y = number(keyword);
        const float z = number(keyword);
        return {x, y, z};
    }

    // A name or file name after `keyword` (any word).
    const Token& word(const Token& keyword, const char* what) {
        skip_stray_opens("after '" + std::string(keyword.text) + "'");
        const Token& t = peek();
        if (t.kind != TokenKind::Word)
            fail(t, "expected " + std::string(what) + " after '" + std::string(keyword.text) +
                        "', found " + describe(t));
        return next();
    }

    static std::string bottom_row(const glm::mat4& m) {
        std::string s;
        for (int c = 0; c < 4; ++c) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%s%g", c ? " " : "", double(m[c][3]));
            s += buf;
        }
        return s;
    }

    // ---- block framing ----------------------------------------------------------------------

    // `[` is optional where a block opens; a second one is not a block opener.
    void open_block() {
        if (peek().kind == TokenKind::Open) next();
    }

    // The next keyword of a block, or nullptr at its closing `]`.
    const Token* next_in_block(const Token& opener, const std::string& block) {
        skip_stray_opens("in " + block + " block opened at " + pos_str(opener));
        const Token& t = next();
        switch (t.kind) {
            case TokenKind::Close: return nullptr;
            case TokenKind::End: fail_unclosed(opener, block);
            case TokenKind::Open:  // skipped above
            case TokenKind::Word: break;
        }
        return &t;
    }

    // Skips to the `]` that closes a block whose opening (if any) is already consumed.
    void skip_to_block_end(const Token& opener, const std::string& block) {
        int depth = 1;
        while (depth > 0) {
            const Token& t = next();
            if (t.kind == TokenKind::End) fail_unclosed(opener, block);
            if (t.kind == TokenKind::Open) ++depth;
            if (t.kind == TokenKind::Close) --depth;
        }
    }

    // Strict: an error with the keyword, the block and a hint. Lenient: a warning, and the
    // numbers or the bracketed block that follow the keyword are skipped.
    void unknown_keyword(const Token& keyword, const std::string& block, const char* expected) {
        const bool is_number = parse_number(keyword.text).status != NumberStatus::Invalid;
        const std::string where = " in " + block + " block";
        if (!options_.lenient) {
            if (is_number)
                fail(keyword, "unexpected number " + describe(keyword) + where +
                                  " (expected a keyword: one of " + expected +
                                  "); does the keyword before it have too many numbers?");
            fail(keyword, "unknown keyword " + describe(keyword) + where + " (expected one of: " +
                              expected + "); use --lenient to skip unknown keywords");
        }
        std::string skipped;
        if (peek().kind == TokenKind::Open) {
            next();
            skip_to_block_end(keyword, "'" + std::string(keyword.text) + "'");
            skipped = " and its bracketed block";
        } else {
            int count = 0;
            while (peek().kind == TokenKind::Word &&
                   parse_number(peek().text).status != NumberStatus::Invalid) {
                next();
                ++count;
            }
            if (count > 0)
                skipped = " and the " + std::to_string(count) +
                          (count == 1 ? " number after it" : " numbers after it");
        }
        warn(loc(keyword), std::string("skipped ") +
                               (is_number ? "unexpected number " : "unknown keyword ") +
                               describe(keyword) + skipped + where + " (lenient mode)");
    }

    // ---- the grammar ------------------------------------------------------------------------

    void parse_file() {
        if (tokens_.size() == 1)
            fail(SourceLoc{file_, 1, 1},  // located like any other error
                 "empty scene file: a scene needs at least 'mastersubgraph root [ ... ]'");
        while (true) {
            skip_stray_opens("at top level");
            if (peek().kind == TokenKind::End) break;
            const Token& t = next();
            if (t.kind == TokenKind::Close)
                fail(t, "unexpected ']' at top level: no block is open");
            if (t.text == "background")
                parse_background(t);
            else if (t.text == "camera")
                parse_camera(t);
            else if (t.text == "light")
                parse_light(t);
            else if (t.text == "mastersubgraph")
                parse_mastersubgraph(t);
            else if (t.text == "trans")
                fail(t,
                     "'trans' at top level: trans blocks belong inside 'mastersubgraph NAME "
                     "[ ... ]' (a top-level trans is the older Brown/Tufts dialect, which is "
                     "not supported)");
            else
                unknown_keyword(t, "top-level", kTopKeywords);
        }
    }

    void parse_background(const Token& opener) {
        open_block();
        while (const Token* k = next_in_block(opener, "background")) {
            if (k->text == "color")
                scene_.background = vec3(*k);
            else
                unknown_keyword(*k, "background", kBackgroundKeywords);
        }
    }

    void parse_camera(const Token& opener) {
        CameraDesc& cam = scene_.camera;  // several camera blocks merge keyword by keyword
        cam.loc = loc(opener);
        open_block();
        while (const Token* k = next_in_block(opener, "camera")) {
            const std::string_view w = k->text;
            if (w == "eye") {
                cam.eye = vec3(*k);
            } else if (w == "look") {
                cam.look = vec3(*k);
                cam.use_focus = false;  // the later of look/focus wins
                camera_view_loc_ = loc(*k);
            } else if (w == "focus") {
                cam.focus = vec3(*k);
                cam.use_focus = true;
                camera_view_loc_ = loc(*k);
            } else if (w == "up") {
                cam.up = vec3(*k);
                camera_up_loc_ = loc(*k);
            } else if (w == "angle") {
                const Token& v = peek();
                cam.angle_deg = number(*k);
                if (!(cam.angle_deg > 0 && cam.angle_deg < 180))
                    fail(v,
                         "camera 'angle' (full vertical field of view) must be between 0 and "
                         "180 degrees, exclusive; found " +
                             num_str(cam.angle_deg));
            } else if (w == "near-far") {
                cam.near_plane = number(*k);
                cam.far_plane = number(*k);
            } else if (w == "aperture") {
                const Token& v = peek();
                cam.aperture = number(*k);
                if (!(cam.aperture >= 0))
                    fail(v, "camera 'aperture' (the lens diameter) must be >= 0; found " + num_str(cam.aperture));
                camera_aperture_loc_ = loc(*k);
            } else if (w == "focaldistance") {
                const Token& v = peek();
                cam.focal_distance = number(*k);
                if (!(cam.focal_distance > 0))
                    fail(v, "camera 'focaldistance' must be > 0; found " + num_str(cam.focal_distance));
            } else {
                unknown_keyword(*k, "camera", kCameraKeywords);
            }
        }
    }

    void parse_light(const Token& opener) {
        LightDesc light;
        light.loc = loc(opener);
        bool has_light_keyword = false, has_ambient = false;
        SourceLoc direction_loc = light.loc, function_loc = light.loc, radius_loc, angle_loc;
        open_block();
        while (const Token* k = next_in_block(opener, "light")) {
            const std::string_view w = k->text;
            bool known = true;
            if (w == "type") {
                const Token& t = word(*k, "a light type (point, directional or spotlight)");
                if (t.text == "point")
                    light.type = LightType::Point;
                else if (t.text == "directional")
                    light.type = LightType::Directional;
                else if (t.text == "spotlight")
                    light.type = LightType::Spot;
                else
                    fail(t, "unknown light type " + describe(t) +
                                " (expected one of: point, directional, spotlight)");
            } else if (w == "position") {
                light.position = vec3(*k);
            } else if (w == "direction") {
                light.direction = vec3(*k);
                direction_loc = loc(*k);
            } else if (w == "color") {
                light.color = vec3(*k);
            } else if (w == "function") {
                light.falloff = vec3(*k);
                function_loc = loc(*k);
            } else if (w == "aperture") {
                const Token& v = peek();
                light.aperture_deg = number(*k);
                if (!(light.aperture_deg > 0 && light.aperture_deg <= 180))
                    fail(v,
                         "light 'aperture' (half-angle of the spot cone) must be in (0, 180] "
                         "degrees; found " +
                             num_str(light.aperture_deg));
            } else if (w == "exponent") {
                const Token& v = peek();
                light.exponent = number(*k);
                if (!(light.exponent >= 0))
                    fail(v, "light 'exponent' must be >= 0; found " + num_str(light.exponent));
            } else if (w == "radius") {
                const Token& v = peek();
                light.radius = number(*k);
                if (!(light.radius >= 0))
                    fail(v, "light 'radius' (of the disc the light is) must be >= 0; found " + num_str(light.radius));
                radius_loc = loc(*k);
            } else if (w == "angle") {
                const Token& v = peek();
                light.angle_deg = number(*k);
                if (!(light.angle_deg >= 0 && light.angle_deg < 180))
                    fail(v, "light 'angle' (the angular diameter of a directional light) must be in [0, 180) "
                            "degrees; found " + num_str(light.angle_deg));
                angle_loc = loc(*k);
            } else if (w == "ambient") {
                scene_.ambient_intensity = vec3(*k);  // global I_a, last one wins
                has_ambient = true;
                known = false;  // not a property of this light
            } else {
                unknown_keyword(*k, "light", kLightKeywords);
                known = false;
            }
            has_light_keyword = has_light_keyword || known;
        }
        if (has_ambient && !has_light_keyword) return;  // an `ambient`-only block is not a light

        if (light.type == LightType::Directional && light.radius > 0)
            fail(radius_loc, "light 'radius' makes a point light or spotlight a disc; a directional light's size "
                             "is its 'angle' (angular diameter in degrees)");
        if (light.type != LightType::Directional && light.angle_deg > 0)
            fail(angle_loc, "light 'angle' (angular diameter) applies to directional lights; a point light or "
                            "spotlight is made larger with 'radius'");
        if (light.type != LightType::Point && !(glm::length(glm::dvec3(light.direction)) > 1e-12))
            fail(direction_loc,
                 std::string("light 'direction' is zero: a ") +
                     (light.type == LightType::Spot ? "spotlight" : "directional light") +
                     " needs a direction");
        if (light.type != LightType::Directional && falloff_can_be_nonpositive(light.falloff)) {
            const glm::vec3& f = light.falloff;
            warn(function_loc, "light 'function " + num_str(f.x) + " " + num_str(f.y) + " " +
                                   num_str(f.z) +
                                   "': the attenuation denominator c + l*d + q*d^2 is <= 0 at "
                                   "some distances; there the light is not attenuated (att = 1)");
        }
        scene_.lights.push_back(light);
    }

    void parse_mastersubgraph(const Token& opener) {
        const Token& name = word(opener, "a name");
        SubgraphDesc sg;
        sg.name = std::string(name.text);
        sg.loc = loc(opener);
        const auto existing = subgraph_index_.find(sg.name);
        if (existing != subgraph_index_.end()) {
            const SourceLoc& first = scene_.subgraphs[existing->second].loc;
            fail(name, "duplicate mastersubgraph " + describe(name) + " (first defined at " +
                           std::to_string(first.line) + ":" + std::to_string(first.col) + ")");
        }
        const std::string block = "mastersubgraph '" + sg.name + "'";
        open_block();
        while (const Token* k = next_in_block(opener, block)) {
            if (k->text == "trans")
                parse_trans(*k, sg);
            else
                unknown_keyword(*k, block, kSubgraphKeywords);
        }
        subgraph_index_.emplace(sg.name, static_cast<int>(scene_.subgraphs.size()));
        scene_.subgraphs.push_back(std::move(sg));
    }

    void parse_trans(const Token& opener, SubgraphDesc& sg) {
        TransDesc trans;
        trans.loc = loc(opener);
        glm::mat4& m = trans.matrix;
        open_block();
        while (const Token* k = next_in_block(opener, "trans")) {
            const std::string_view w = k->text;
            // M = T1 · T2 · … · Tn: each transform multiplies on the right, so the last one
            // written is applied to the object first (scene-format.md §3).
            if (w == "translate") {
                m = m * translation_matrix(vec3(*k));
            } else if (w == "scale") {
                m = m * scale_matrix(vec3(*k));
            } else if (w == "rotate") {
                const glm::vec3 axis = vec3(*k);
                const float degrees = number(*k);
                const auto r = rotation_matrix(axis, degrees);
                if (!r)
                    fail(*k,
                         "'rotate' axis is zero: expected 'rotate ax ay az degrees' with a "
                         "non-zero axis");
                m = m * *r;
            } else if (w == "matrixRC" || w == "matrixCR") {
                std::array<float, 16> v{};
                for (float& x : v) x = number(*k);
                const glm::mat4 given = w == "matrixRC" ? matrix_from_rows(v) : matrix_from_columns(v);
                // Shapes are intersected through the inverse of an affine map: a projective
                // bottom row would be dropped without a word, so it is refused instead.
                if (given[0][3] != 0 || given[1][3] != 0 || given[2][3] != 0 || given[3][3] != 1)
                    fail(*k, "'" + std::string(w) + "' is not an affine transform: its last row must be "
                             "0 0 0 1, found " + bottom_row(given));
                m = m * given;
            } else if (w == "object") {
                parse_object(*k, trans);
            } else if (w == "subgraph") {
                const Token& name = word(*k, "a subgraph name");
                trans.subgraphs.push_back({std::string(name.text), loc(name)});
            } else if (w == "trans") {
                fail(*k, "'trans' inside the trans block opened at " + pos_str(opener) +
                             ": trans blocks do not nest (close the first one with ']', or use "
                             "a mastersubgraph and 'subgraph NAME')");
            } else {
                unknown_keyword(*k, "trans", kTransKeywords);
            }
        }
        if (is_singular(m))
            fail(opener, "singular transform in the trans block opened at " + pos_str(opener) +
                             ": its matrix cannot be inverted (a zero scale, or a degenerate "
                             "or non-finite matrix)");
        sg.children.push_back(std::move(trans));
    }

    void parse_object(const Token& opener, TransDesc& trans) {
        skip_stray_opens("after 'object'");
        const Token& type = peek();
        if (type.kind != TokenKind::Word)
            fail(type, std::string("expected an object type after 'object' (one of: ") +
                           kShapeNames + "), found " + describe(type));
        next();
        ObjectDesc obj;
        obj.loc = loc(opener);
        if (type.text == "cube")
            obj.kind = ShapeKind::Cube;
        else if (type.text == "cylinder")
            obj.kind = ShapeKind::Cylinder;
        else if (type.text == "cone")
            obj.kind = ShapeKind::Cone;
        else if (type.text == "sphere")
            obj.kind = ShapeKind::Sphere;
        else if (type.text == "mesh")
            obj.kind = ShapeKind::Mesh;
        else {
            if (!options_.lenient)
                fail(type, "unknown object type " + describe(type) + " (expected one of: " +
                               kShapeNames + "); use --lenient to skip objects of unknown type");
            warn(loc(type), "skipped object of unknown type " + describe(type) +
                                " with its block (lenient mode)");
            open_block();
            skip_to_block_end(opener, "object");
            return;
        }
        MaterialDesc& mat = obj.material;
        open_block();
        while (const Token* k = next_in_block(opener, "object")) {
            const std::string_view w = k->text;
            if (w == "ambient")
                mat.ambient = vec3(*k);
            else if (w == "diffuse")
                mat.diffuse = vec3(*k);
            else if (w == "specular")
                mat.specular = vec3(*k);
            else if (w == "reflect")
                mat.reflect = vec3(*k);
            else if (w == "transparent")
                mat.transparent = vec3(*k);
            else if (w == "emit")
                mat.emit = vec3(*k);
            else if (w == "shine")
                mat.shine = number(*k);
            else if (w == "gloss") {
                const Token& v = peek();
                mat.gloss = number(*k);
                if (!(mat.gloss > 0))
                    fail(v, "'gloss' (the exponent of the blur lobe; large = sharp) must be > 0; found " +
                                num_str(mat.gloss));
            }
            else if (w == "ior") {
                const Token& v = peek();
                mat.ior = number(*k);
                if (!(mat.ior > 0)) fail(v, "'ior' must be > 0; found " + num_str(mat.ior));
            } else if (w == "texture") {
                TextureRef tex;
                tex.loc = loc(*k);
                tex.file = std::string(word(*k, "a texture file name").text);
                const Token& u = peek();
                tex.repeat_u = number(*k);
                if (!(tex.repeat_u > 0))
                    fail(u, "texture repeat count u must be > 0; found " + num_str(tex.repeat_u));
                const Token& v = peek();
                tex.repeat_v = number(*k);
                if (!(tex.repeat_v > 0))
                    fail(v, "texture repeat count v must be > 0; found " + num_str(tex.repeat_v));
                mat.texture = std::move(tex);
            } else if (w == "file") {
                // §9.3: the OBJ file of a mesh, looked up like a texture when the scene is loaded.
                if (obj.kind != ShapeKind::Mesh)
                    fail(*k, "'file' names the OBJ file of an 'object mesh'; a " + std::string(shape_name(obj.kind)) +
                                 " has no file");
                obj.mesh_loc = loc(*k);
                obj.mesh_file = std::string(word(*k, "a mesh file name (an OBJ file)").text);
            } else {
                unknown_keyword(*k, "object", kObjectKeywords);
            }
        }
        if (obj.kind == ShapeKind::Mesh && obj.mesh_file.empty())
            fail(opener, "'object mesh' needs its OBJ file: 'file PATH' in the object block (scene-format.md §9.3)");
        trans.objects.push_back(std::move(obj));
    }

    // ---- checks that need the whole file ----------------------------------------------------

    void check_whole_file() {
        if (auto d = check_subgraph_references(scene_)) fail(d->loc, d->message);
        if (auto d = check_subgraph_cycles(scene_)) fail(d->loc, d->message);
        const auto root = subgraph_index_.find("root");
        scene_.root = root == subgraph_index_.end() ? -1 : root->second;
        if (scene_.root < 0) {
            // Reported at the top of the file, like an empty one: there is no one place to point at.
            std::string defined;
            for (std::size_t i = 0; i < scene_.subgraphs.size() && i < 5; ++i)
                defined += (i ? ", '" : " (it defines '") + scene_.subgraphs[i].name + "'";
            if (scene_.subgraphs.size() > 5) defined += ", ...";
            if (!defined.empty()) defined += ")";
            fail(SourceLoc{file_, 1, 1},
                 "no 'mastersubgraph root' in the file" + defined + ": root is the scene and is required");
        }
        if (auto d = check_camera(scene_.camera, camera_up_loc_, camera_view_loc_))
            fail(d->loc, d->message);
        const CameraDesc& cam = scene_.camera;
        if (cam.aperture > 0 && !cam.use_focus && !(cam.focal_distance > 0))
            fail(camera_aperture_loc_, "camera 'aperture' " + num_str(cam.aperture) +
                                           " needs a distance to focus at: give 'focaldistance F', or a 'focus' "
                                           "point (the camera looks along 'look', so there is none)");
    }
};

}  // namespace

ParseResult parse_scene_text(std::string_view text, const std::string& file_name,
                             const ParseOptions& options) {
    return Parser(text, file_name, options).run();
}

ParseResult parse_scene_file(const std::string& path, const ParseOptions& options) {
    ParseResult result;
    auto fail = [&](const std::string& why) {
        result.diagnostics.push_back(
            {Severity::Error, SourceLoc{path, 0, 0}, "cannot read scene file: " + why});
        result.unreadable = true;
        return result;
    };
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return fail("it is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) return fail(std::strerror(errno));
    std::string text;
    char buffer[65536];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
        text.append(buffer, static_cast<size_t>(in.gcount()));
    if (in.bad()) return fail("read error");
    return parse_scene_text(text, path, options);
}

}  // namespace whitted
