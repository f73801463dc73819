// The blocks' keywords (scene-format.md §2, §6, §9.4): background, camera, light, mastersubgraph,
// trans, object and material. The framing they use (read_block, errors, dialects) is in parser_impl.h.
#include "parse/parser_impl.h"

namespace whitted::parse_detail {

void Parser::parse_background(const Token& opener) {
    open_block();
    read_block(opener, "background", [&](const Token& k) {
        if (find_keyword(k.text) == Keyword::Color)
            scene_.background = vec3(k);
        else
            unknown_keyword(k, "background", kBackgroundKeywords);
    });
}

void Parser::parse_camera(const Token& opener) {
    CameraDesc& cam = scene_.camera;  // several camera blocks merge keyword by keyword
    cam.loc = loc(opener);
    open_block();
    read_block(opener, "camera", [&](const Token& k) {
        const Keyword w = find_keyword(k.text);
        if (w == Keyword::Eye) {
            cam.eye = vec3(k);
        } else if (w == Keyword::Look) {
            cam.look = vec3(k);
            cam.use_focus = false;  // the later of look/focus wins
            camera_view_loc_ = loc(k);
        } else if (w == Keyword::Focus) {
            cam.focus = vec3(k);
            cam.use_focus = true;
            camera_view_loc_ = loc(k);
        } else if (w == Keyword::Up) {
            cam.up = vec3(k);
            camera_up_loc_ = loc(k);
        } else if (w == Keyword::Angle) {
            const Token v = peek();
            cam.angle_deg = number(k);
            if (!(cam.angle_deg > 0 && cam.angle_deg < 180))
                error(v,
                      "camera 'angle' (full vertical field of view) must be between 0 and "
                      "180 degrees, exclusive; found " +
                          num_str(cam.angle_deg));
        } else if (w == Keyword::NearFar) {
            cam.near_plane = number(k);
            cam.far_plane = number(k);
        } else if (w == Keyword::Aperture) {
            const Token v = peek();
            cam.aperture = number(k);
            if (!(cam.aperture >= 0))
                error(v, "camera 'aperture' (the lens diameter) must be >= 0; found " + num_str(cam.aperture));
            camera_aperture_loc_ = loc(k);
        } else if (w == Keyword::Focaldistance) {
            const Token v = peek();
            cam.focal_distance = number(k);
            if (!(cam.focal_distance > 0))
                error(v, "camera 'focaldistance' must be > 0; found " + num_str(cam.focal_distance));
        } else {
            unknown_keyword(k, "camera", kCameraKeywords);
        }
    });
}

void Parser::parse_light(const Token& opener) {
    PendingLight light;
    LightDesc& desc = light.desc;
    desc.loc = loc(opener);
    light.direction_loc = light.function_loc = desc.loc;
    bool has_light_keyword = false, has_ambient = false;
    open_block();
    const bool ok = read_block(opener, "light", [&](const Token& k) {
        const Keyword w = find_keyword(k.text);
        bool known = true;
        if (w == Keyword::Type) {
            const Token t = word(k, "a light type (point, directional or spotlight)");
            light.has_type = true;
            const Keyword type = find_keyword(t.text);
            if (type == Keyword::Point)
                desc.type = LightType::Point;
            else if (type == Keyword::Directional)
                desc.type = LightType::Directional;
            else if (type == Keyword::Spotlight)
                desc.type = LightType::Spot;
            else
                error(t, "unknown light type " + describe(t) + did_you_mean(t.text, kLightTypes) +
                             " (expected one of: " + kLightTypes + ")");
        } else if (w == Keyword::Position) {
            desc.position = vec3(k);
            light.has_position = true;
        } else if (w == Keyword::Direction) {
            desc.direction = vec3(k);
            light.direction_loc = loc(k);
            light.has_direction = true;
        } else if (w == Keyword::Color) {
            desc.color = vec3(k);
            light.has_color = true;
        } else if (w == Keyword::Function) {
            desc.falloff = vec3(k);
            light.function_loc = loc(k);
        } else if (w == Keyword::Aperture) {
            const Token v = peek();
            desc.aperture_deg = number(k);
            if (!(desc.aperture_deg > 0 && desc.aperture_deg <= 180))
                error(v,
                      "light 'aperture' (half-angle of the spot cone) must be in (0, 180] "
                      "degrees; found " +
                          num_str(desc.aperture_deg));
        } else if (w == Keyword::Exponent) {
            const Token v = peek();
            desc.exponent = number(k);
            if (!(desc.exponent >= 0))
                error(v, "light 'exponent' must be >= 0; found " + num_str(desc.exponent));
        } else if (w == Keyword::Radius) {
            const Token v = peek();
            desc.radius = number(k);
            if (!(desc.radius >= 0))
                error(v, "light 'radius' (of the disc the light is) must be >= 0; found " + num_str(desc.radius));
            light.radius_loc = loc(k);
        } else if (w == Keyword::Angle) {
            const Token v = peek();
            desc.angle_deg = number(k);
            if (!(desc.angle_deg >= 0 && desc.angle_deg < 180))
                error(v, "light 'angle' (the angular diameter of a directional light) must be in [0, 180) "
                         "degrees; found " + num_str(desc.angle_deg));
            light.angle_loc = loc(k);
        } else if (w == Keyword::Number) {
            // Brown/Tufts: the light's identifier (§9.4); it has no effect on the picture.
            mark_dialect(Dialect::BrownTufts, k, "'light [ number ...'");
            number(k);
        } else if (w == Keyword::Ambient) {
            scene_.ambient_intensity = vec3(k);  // global I_a, last one wins
            has_ambient = true;
            known = false;  // not a property of this light
        } else {
            unknown_keyword(k, "light", kLightKeywords);
            known = false;
        }
        has_light_keyword = has_light_keyword || known;
    });
    if (!ok || (has_ambient && !has_light_keyword)) return;  // an `ambient`-only block is not a light
    lights_.push_back(light);
}

void Parser::finish_lights() {
    for (PendingLight& light : lights_) {
        LightDesc& desc = light.desc;
        if (brown()) {
            // That course's renderer: lights default to white at (3, 3, 3), and a light that
            // gives a direction but no position is directional.
            if (!light.has_position) desc.position = {3, 3, 3};
            if (!light.has_color) desc.color = {1, 1, 1};
            if (!light.has_type && light.has_direction && !light.has_position)
                desc.type = LightType::Directional;
        }
        if (desc.type == LightType::Directional && desc.radius > 0) {
            error(light.radius_loc, "light 'radius' makes a point light or spotlight a disc; a directional light's "
                                    "size is its 'angle' (angular diameter in degrees)");
            continue;
        }
        if (desc.type != LightType::Directional && desc.angle_deg > 0) {
            error(light.angle_loc, "light 'angle' (angular diameter) applies to directional lights; a point light "
                                   "or spotlight is made larger with 'radius'");
            continue;
        }
        if (desc.type != LightType::Point && !(glm::length(glm::dvec3(desc.direction)) > 1e-12)) {
            error(light.direction_loc,
                  std::string("light 'direction' is zero: a ") +
                      (desc.type == LightType::Spot ? "spotlight" : "directional light") +
                      " needs a direction");
            continue;
        }
        if (desc.type != LightType::Directional && falloff_can_be_nonpositive(desc.falloff)) {
            const glm::vec3& f = desc.falloff;
            warn(light.function_loc,
                 "light 'function " + num_str(f.x) + " " + num_str(f.y) + " " + num_str(f.z) +
                     "': the attenuation denominator c + l*d + q*d^2 is <= 0 at "
                     "some distances; there the light is not attenuated (att = 1)");
        }
        scene_.lights.push_back(desc);
    }
}

void Parser::parse_mastersubgraph(const Token& opener) {
    const bool ok = mark_dialect(Dialect::Labs, opener, "'mastersubgraph'");
    const Token name = word(opener, "a name");
    SubgraphDesc sg;
    sg.name = std::string(name.text);
    sg.loc = loc(opener);
    const auto existing = subgraph_index_.find(sg.name);
    bool duplicate = false;
    if (existing != subgraph_index_.end()) {
        const SourceLoc& first = scene_.subgraphs[existing->second].loc;
        error(name, "duplicate mastersubgraph " + describe(name) + " (first defined at " +
                        std::to_string(first.line) + ":" + std::to_string(first.col) + ")");
        duplicate = true;
    }
    const std::string block = "mastersubgraph '" + sg.name + "'";
    open_block();
    // Kept after an error inside (its references still resolve); a duplicate is dropped.
    read_block(opener, block, [&](const Token& k) {
        if (find_keyword(k.text) == Keyword::Trans)
            parse_trans(k, sg);
        else
            unknown_keyword(k, block, kSubgraphKeywords);
    });
    if (duplicate || !ok) return;
    subgraph_index_.emplace(sg.name, static_cast<int>(scene_.subgraphs.size()));
    scene_.subgraphs.push_back(std::move(sg));
}

void Parser::parse_trans(const Token& opener, SubgraphDesc& sg) {
    TransDesc trans;
    trans.loc = loc(opener);
    glm::mat4& m = trans.matrix;
    const float time = options_.time;
    Motion motion;  // the same product kept as a function of time (kept only if the block moves)
    open_block();
    read_block(opener, "trans", [&](const Token& k) {
        const Keyword w = find_keyword(k.text);
        // M = T1 · T2 · … · Tn: each transform multiplies on the right, so the last one
        // written is applied to the object first (scene-format.md §3).
        if (w == Keyword::Translate) {
            const glm::mat4 t = translation_matrix(vec3(k));
            m = m * t;
            motion.then_matrix(glm::dmat4(t));
        } else if (w == Keyword::Scale) {
            const glm::mat4 s = scale_matrix(vec3(k));
            m = m * s;
            motion.then_matrix(glm::dmat4(s));
        } else if (w == Keyword::Rotate || w == Keyword::Angularrate) {
            // angularrate ax ay az rate: `rotate ax ay az (rate·t)` at scene time t (§9.4).
            const bool rotate = w == Keyword::Rotate;
            if (!rotate) scene_.moves = true;
            const glm::vec3 axis = vec3(k);
            const float amount = number(k);
            const float degrees = rotate ? amount : amount * time;
            const auto r = rotation_matrix(axis, degrees);
            if (!r)
                error(k, "'" + std::string(k.text) + "' axis is zero: expected '" + std::string(k.text) +
                             " ax ay az " + (rotate ? "degrees" : "rate") + "' with a non-zero axis");
            else if (rotate || time != 0)  // at t = 0 exactly the file without it
                m = m * *r;
            if (r && rotate) motion.then_matrix(glm::dmat4(*r));
            else if (r) motion.then_spin(glm::dvec3(axis), amount);
        } else if (w == Keyword::Velocity) {
            // velocity x y z: `translate t·x t·y t·z` at scene time t (§9.4).
            const glm::vec3 v = vec3(k);
            scene_.moves = true;
            if (time != 0) m = m * translation_matrix(time * v);
            motion.then_velocity(glm::dvec3(v));
        } else if (w == Keyword::MatrixRC || w == Keyword::MatrixCR) {
            std::array<float, 16> v{};
            for (float& x : v) x = number(k);
            const glm::mat4 given = w == Keyword::MatrixRC ? matrix_from_rows(v) : matrix_from_columns(v);
            // Shapes are intersected through the inverse of an affine map: a projective
            // bottom row would be dropped without a word, so it is refused instead.
            if (given[0][3] != 0 || given[1][3] != 0 || given[2][3] != 0 || given[3][3] != 1)
                error(k, "'" + std::string(k.text) + "' is not an affine transform: its last row must be "
                         "0 0 0 1, found " + bottom_row(given));
            else
                m = m * given;
            motion.then_matrix(glm::dmat4(given));
        } else if (w == Keyword::Object) {
            parse_object(k, trans);
        } else if (w == Keyword::Subgraph) {
            const Token name = word(k, "a subgraph name");
            trans.subgraphs.push_back({std::string(name.text), loc(name)});
        } else if (w == Keyword::Trans) {
            fail(k, "'trans' inside the trans block opened at " + pos_str(opener) +
                        ": trans blocks do not nest (close the first one with ']', or use "
                        "a mastersubgraph and 'subgraph NAME')");
        } else {
            unknown_keyword(k, "trans", kTransKeywords);
        }
    });
    if (is_singular(m))
        error(opener, "singular transform in the trans block opened at " + pos_str(opener) +
                          ": its matrix cannot be inverted (a zero scale, or a degenerate "
                          "or non-finite matrix)");
    if (motion.moves()) trans.motion = std::move(motion);
    sg.children.push_back(std::move(trans));
}

void Parser::skip_object(const Token& opener, const Token& type, const std::string& why) {
    warn(loc(type), why);
    open_block();
    skip_to_block_end(opener, "object");
}

void Parser::parse_object(const Token& opener, TransDesc& trans) {
    skip_stray_opens([] { return "after 'object'"; });
    const Token type = peek();
    if (type.kind != TokenKind::Word)
        fail(type, std::string("expected an object type after 'object' (one of: ") +
                       kShapeNames + "), found " + describe(type));
    next();
    ObjectDesc obj;
    obj.loc = loc(opener);
    const std::string_view t = type.text;
    const Keyword shape = find_keyword(t);
    if (shape == Keyword::Cube)
        obj.kind = ShapeKind::Cube;
    else if (shape == Keyword::Cylinder)
        obj.kind = ShapeKind::Cylinder;
    else if (shape == Keyword::Cone)
        obj.kind = ShapeKind::Cone;
    else if (shape == Keyword::Sphere)
        obj.kind = ShapeKind::Sphere;
    else if (shape == Keyword::Ellipsoid)
        obj.kind = ShapeKind::Ellipsoid;
    else if (shape == Keyword::Cactus || shape == Keyword::Cow)
        return skip_object(opener, type, "object " + describe(type) + " skipped: a special shape of another "
                                          "lab whose geometry did not survive (scene-format.md §9.4)");
    else if (shape == Keyword::Mesh && brown())
        return skip_object(opener, type, "object 'mesh' skipped: its 'meshfile' is in the Brown/Tufts "
                                          "course's own mesh format, which whitted does not read");
    else if (shape == Keyword::Mesh)
        obj.kind = ShapeKind::Mesh;
    else {
        if (!options_.lenient) {
            error(type, "unknown object type " + describe(type) + did_you_mean(t, kAllShapeWords) +
                            " (expected one of: " + kShapeNames +
                            "); use --lenient to skip objects of unknown type");
            open_block();
            skip_to_block_end(opener, "object");
            return;
        }
        return skip_object(opener, type, "skipped object of unknown type " + describe(type) +
                                              " with its block (lenient mode)");
    }
    MaterialDesc& mat = obj.material;
    open_block();
    const bool ok = read_block(opener, "object", [&](const Token& k) {
        const Keyword w = find_keyword(k.text);
        if (w != Keyword::File) return parse_material(k, w, mat);
        // §9.3: the OBJ file of a mesh, looked up like a texture when the scene is loaded.
        if (obj.kind != ShapeKind::Mesh)
            fail(k, "'file' names the OBJ file of an 'object mesh'; a " + std::string(shape_name(obj.kind)) +
                        " has no file");
        obj.mesh_loc = loc(k);
        obj.mesh_file = std::string(word(k, "a mesh file name (an OBJ file)").text);
    });
    if (ok && obj.kind == ShapeKind::Mesh && obj.mesh_file.empty()) {
        error(opener, "'object mesh' needs its OBJ file: 'file PATH' in the object block (scene-format.md §9.3)");
        return;
    }
    if (ok) trans.objects.push_back(std::move(obj));
}

void Parser::parse_material(const Token& k, Keyword w, MaterialDesc& mat) {
    if (w == Keyword::Ambient)
        mat.ambient = vec3(k);
    else if (w == Keyword::Diffuse)
        mat.diffuse = vec3(k);
    else if (w == Keyword::Specular)
        mat.specular = vec3(k);
    else if (w == Keyword::Reflect)
        mat.reflect = vec3(k);
    else if (w == Keyword::Transparent)
        mat.transparent = vec3(k);
    else if (w == Keyword::Emit)
        mat.emit = vec3(k);
    else if (w == Keyword::Shine)
        mat.shine = number(k);
    else if (w == Keyword::Gloss) {
        const Token v = peek();
        mat.gloss = number(k);
        if (!(mat.gloss > 0))
            error(v, "'gloss' (the exponent of the blur lobe; large = sharp) must be > 0; found " + num_str(mat.gloss));
    }
    else if (w == Keyword::Ior) {
        const Token v = peek();
        mat.ior = number(k);
        if (!(mat.ior > 0)) error(v, "'ior' must be > 0; found " + num_str(mat.ior));
    } else if (w == Keyword::Texture) {
        TextureRef tex;
        tex.loc = loc(k);
        tex.file = std::string(word(k, "a texture file name").text);
        tex.loose_lookup = brown();
        const Token u = peek();
        tex.repeat_u = number(k);
        if (!(tex.repeat_u > 0))
            error(u, "texture repeat count u must be > 0; found " + num_str(tex.repeat_u));
        const Token v = peek();
        tex.repeat_v = number(k);
        if (!(tex.repeat_v > 0))
            error(v, "texture repeat count v must be > 0; found " + num_str(tex.repeat_v));
        mat.texture = std::move(tex);
    } else if (w == Keyword::Alpha) {
        // An OpenGL opacity some authors wrote (§9.4): read, and ignored with one warning.
        number(k);
        if (!alpha_warned_)
            warn(loc(k), "'alpha' has no effect and is ignored (transparency is 'transparent r g b'); "
                         "this warning is given once per file");
        alpha_warned_ = true;
    } else if (w == Keyword::Blend && brown()) {
        const Token v = peek();
        const float b = number(k);
        if (!(b >= 0 && b <= 1))
            error(v, "'blend' (the texture's share of the diffuse colour) must be in [0, 1]; found " + num_str(b));
        mat.blend = b;
    } else {
        unknown_keyword(k, "object", brown() ? kBrownObjectKeywords : kObjectKeywords);
    }
}

}  // namespace whitted::parse_detail
