#include "parse/parser.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <utility>

#include "parse/binary_sniff.h"
#include "parse/falloff.h"
#include "parse/lexer.h"
#include "parse/number.h"
#include "parse/scene_checks.h"
#include "parse/suggest.h"
#include "parse/transforms.h"

namespace whitted {
namespace {

// Thrown after a syntax error has been recorded: the innermost block being read catches it and
// skips to its own end, and parsing goes on, so one run reports every problem of the file.
// Unwinding keeps the recursive-descent code straight.
struct ParseStop {};
// Thrown when nothing more can be read (end of file inside a block): ends the parse.
struct ParseAbort {};

// Errors listed in full; past this many, only counted (a cascade helps nobody).
constexpr int kMaxErrors = 20;

// The keywords each block accepts, for "expected one of" hints.
constexpr const char* kTopKeywords = "background, camera, light, mastersubgraph";
constexpr const char* kTopWords = "background, camera, light, mastersubgraph, trans";  // for suggestions
constexpr const char* kBackgroundKeywords = "color";
constexpr const char* kCameraKeywords = "eye, look, focus, up, angle, near-far";
constexpr const char* kLightKeywords =
    "type, position, direction, color, function, aperture, exponent, ambient, number";
constexpr const char* kLightTypes = "point, directional, spotlight";
constexpr const char* kSubgraphKeywords = "trans";
constexpr const char* kTransKeywords =
    "translate, scale, rotate, matrixRC, matrixCR, velocity, angularrate, object, subgraph";
constexpr const char* kObjectKeywords =
    "ambient, diffuse, specular, reflect, transparent, emit, shine, ior, texture, alpha";
constexpr const char* kBrownObjectKeywords =
    "ambient, diffuse, specular, reflect, transparent, emit, shine, ior, texture, alpha, blend";
constexpr const char* kShapeNames = "cube, cylinder, cone, sphere, ellipsoid";
// Shapes of other labs whose geometry did not survive (§9.4): skipped with a warning.
constexpr const char* kLostShapes = "cactus, cow";
constexpr const char* kAllShapeWords = "cube, cylinder, cone, sphere, ellipsoid, cactus, cow, mesh";

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

// A light as written, with what it left out: the Brown/Tufts dialect gives the missing words
// other meanings (§9.4), and the dialect is known only once the whole file has been read.
struct PendingLight {
    LightDesc desc;
    bool has_type = false, has_position = false, has_direction = false, has_color = false;
    SourceLoc direction_loc, function_loc;
};

class Parser {
public:
    Parser(std::string_view text, const std::string& file, const ParseOptions& options)
        : text_(text), file_(file), options_(options) {
        scene_.path = file;
    }

    ParseResult run() {
        ParseResult result;
        try {
            if (auto kind = binary_file_kind(text_)) {
                error(SourceLoc{file_, 1, 1}, "this is not a scene file (it looks like " + *kind + ")");
                throw ParseAbort{};
            }
            tokens_ = tokenize(text_);
            parse_file();
        } catch (const ParseAbort&) {
            // Recorded already; nothing after it can be read.
        }
        if (!aborted_) check_whole_file();
        finish_diagnostics();
        result.diagnostics = std::move(diags_);
        if (!has_errors(result.diagnostics)) result.scene = std::move(scene_);
        return result;
    }

private:
    std::string_view text_;
    std::vector<Token> tokens_;
    size_t pos_ = 0;
    const std::string& file_;
    ParseOptions options_;
    std::vector<Diagnostic> diags_;
    int errors_ = 0;            // recorded or not
    SourceLoc first_unlisted_;  // of the first error past kMaxErrors
    bool aborted_ = false;
    SceneDescription scene_;
    SourceLoc camera_up_loc_, camera_view_loc_;            // line 0 until written
    std::unordered_map<std::string, int> subgraph_index_;  // for duplicates, without O(n²)
    std::vector<PendingLight> lights_;
    // The dialect, from the first word that decides it (§9.4), and where that word was.
    std::optional<Dialect> dialect_;
    SourceLoc dialect_loc_;
    std::string dialect_word_;
    bool mix_reported_ = false, alpha_warned_ = false;
    std::optional<SubgraphDesc> implicit_root_;  // Brown/Tufts: the top-level trans blocks

    // ---- tokens and diagnostics -------------------------------------------------------------

    const Token& peek() const { return tokens_[pos_]; }
    const Token& next() {
        const Token& t = tokens_[pos_];
        if (t.kind != TokenKind::End) ++pos_;  // End repeats forever: no reading past the end
        return t;
    }
    SourceLoc loc(const Token& t) const { return {file_, t.line, t.col}; }

    // Records an error and goes on (the tokens are in a known state).
    void error(const SourceLoc& at, std::string message) {
        if (++errors_ <= kMaxErrors)
            diags_.push_back({Severity::Error, at, std::move(message)});
        else if (errors_ == kMaxErrors + 1)
            first_unlisted_ = at;
    }
    void error(const Token& at, std::string message) { error(loc(at), std::move(message)); }
    // Records an error and unwinds to the innermost block, which skips to its end.
    [[noreturn]] void fail(const SourceLoc& at, std::string message) {
        error(at, std::move(message));
        throw ParseStop{};
    }
    [[noreturn]] void fail(const Token& at, std::string message) {
        fail(loc(at), std::move(message));
    }
    void warn(const SourceLoc& at, std::string message) {
        diags_.push_back({Severity::Warning, at, std::move(message)});
    }

    // Position order (whole-file checks come last otherwise), then the count of the unlisted.
    void finish_diagnostics() {
        std::stable_sort(diags_.begin(), diags_.end(), [](const Diagnostic& a, const Diagnostic& b) {
            return std::pair(a.loc.line, a.loc.col) < std::pair(b.loc.line, b.loc.col);
        });
        if (errors_ > kMaxErrors)
            diags_.push_back({Severity::Error, first_unlisted_,
                              std::to_string(errors_ - kMaxErrors) + " more error" +
                                  (errors_ - kMaxErrors == 1 ? "" : "s") + " not listed (the first of them is here)"});
    }

    // A '[' that opens no block: the reference ignores it wherever it appears (spec §1), so we do
    // too, with a warning, since it often means the brackets around it do not match.
    void skip_stray_opens(const std::string& where) {
        while (peek().kind == TokenKind::Open)
            warn(loc(next()), "'[' " + where + " opens no block and is ignored ('[' belongs after "
                              "a block keyword such as 'trans' or 'object TYPE')");
    }

    [[noreturn]] void fail_unclosed(const Token& opener, const std::string& block) {
        error(peek(), "unexpected end of file: " + block + " block opened at " + pos_str(opener) +
                          " is not closed (missing ']')");
        aborted_ = true;
        throw ParseAbort{};
    }

    // ---- dialects (§9.4) --------------------------------------------------------------------

    // `word` at `at` decides the dialect; a file that has already decided the other way mixes
    // the two, which is an error (reported once). Returns false then.
    bool mark_dialect(Dialect d, const Token& at, const std::string& word) {
        if (!dialect_) {
            dialect_ = d;
            dialect_loc_ = loc(at);
            dialect_word_ = word;
            return true;
        }
        if (*dialect_ == d) return true;
        if (!mix_reported_)
            error(at, "this file mixes two dialects: " + word + " is the " + dialect_name(d) + " form, but " +
                          dialect_word_ + " at " + std::to_string(dialect_loc_.line) + ":" +
                          std::to_string(dialect_loc_.col) + " made it a " + dialect_name(*dialect_) +
                          " file; a scene is written in one or the other (scene-format.md §9.4)");
        mix_reported_ = true;
        return false;
    }
    bool brown() const { return dialect_ == Dialect::BrownTufts; }

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

    // Reads a block's keywords up to its `]`, handing each to `on_keyword`. After an error in
    // one of them, the rest of the block is skipped (error recovery); returns false then.
    template <class OnKeyword>
    bool read_block(const Token& opener, const std::string& block, OnKeyword&& on_keyword) {
        while (const Token* k = next_in_block(opener, block)) {
            try {
                on_keyword(*k);
            } catch (const ParseStop&) {
                if (peek().kind == TokenKind::End) {  // the error was the end of the file: said
                    aborted_ = true;
                    throw ParseAbort{};
                }
                skip_to_block_end(opener, block);
                return false;
            }
        }
        return true;
    }

    // An unknown keyword: in strict mode an error (with "did you mean" when a valid word is close),
    // in lenient mode a warning; either way the numbers or the bracketed block that follow it are
    // skipped and reading goes on.
    void unknown_keyword(const Token& keyword, const std::string& block, const char* expected,
                         const char* suggestions = nullptr) {
        const bool is_number = parse_number(keyword.text).status != NumberStatus::Invalid;
        const std::string where = " in " + block + " block";
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
        if (!options_.lenient) {
            if (is_number)
                error(keyword, "unexpected number " + describe(keyword) + where +
                                   " (expected a keyword: one of " + expected +
                                   "); does the keyword before it have too many numbers?");
            else
                error(keyword, "unknown keyword " + describe(keyword) + where +
                                   did_you_mean(keyword.text, suggestions ? suggestions : expected) +
                                   " (expected one of: " + expected +
                                   "); use --lenient to skip unknown keywords");
            return;
        }
        warn(loc(keyword), std::string("skipped ") +
                               (is_number ? "unexpected number " : "unknown keyword ") +
                               describe(keyword) + skipped + where + " (lenient mode)");
    }

    // ---- the grammar ------------------------------------------------------------------------

    void parse_file() {
        if (tokens_.size() == 1)
            fail_empty();
        while (true) {
            skip_stray_opens("at top level");
            if (peek().kind == TokenKind::End) break;
            const Token& t = next();
            try {
                parse_top_level(t);
            } catch (const ParseStop&) {
                resync_top_level();
            }
        }
        if (brown()) {  // the top-level trans blocks are the scene (§9.4)
            if (!implicit_root_) {
                implicit_root_.emplace();
                implicit_root_->name = "root";
                implicit_root_->loc = dialect_loc_;
            }
            subgraph_index_.emplace("root", static_cast<int>(scene_.subgraphs.size()));
            scene_.subgraphs.push_back(std::move(*implicit_root_));
            scene_.dialect = Dialect::BrownTufts;
        }
        finish_lights();
    }

    [[noreturn]] void fail_empty() {
        error(SourceLoc{file_, 1, 1},  // located like any other error
              "empty scene file: a scene needs at least 'mastersubgraph root [ ... ]'");
        aborted_ = true;
        throw ParseAbort{};
    }

    void parse_top_level(const Token& t) {
        if (t.kind == TokenKind::Close) {
            error(t, "unexpected ']' at top level: no block is open");
            return;
        }
        if (t.text == "background")
            parse_background(t);
        else if (t.text == "camera")
            parse_camera(t);
        else if (t.text == "light")
            parse_light(t);
        else if (t.text == "mastersubgraph")
            parse_mastersubgraph(t);
        else if (t.text == "trans")
            parse_top_level_trans(t);
        else
            unknown_keyword(t, "top-level", kTopKeywords, kTopWords);
    }

    // After an error outside any block (a mastersubgraph without a name): on to the next word
    // that begins a top-level block.
    void resync_top_level() {
        while (peek().kind != TokenKind::End) {
            const std::string_view w = peek().text;
            if (peek().kind == TokenKind::Word &&
                (w == "background" || w == "camera" || w == "light" || w == "mastersubgraph" ||
                 (w == "trans" && brown())))
                return;
            next();
        }
    }

    // Brown/Tufts: a trans block at top level belongs to the implicit root.
    void parse_top_level_trans(const Token& t) {
        const bool ok = mark_dialect(Dialect::BrownTufts, t, "'trans' at top level");
        if (!implicit_root_) {
            implicit_root_.emplace();
            implicit_root_->name = "root";
            implicit_root_->loc = loc(t);
        }
        SubgraphDesc discarded;  // read on to find the file's other errors, then dropped
        parse_trans(t, ok ? *implicit_root_ : discarded);
    }

    void parse_background(const Token& opener) {
        open_block();
        read_block(opener, "background", [&](const Token& k) {
            if (k.text == "color")
                scene_.background = vec3(k);
            else
                unknown_keyword(k, "background", kBackgroundKeywords);
        });
    }

    void parse_camera(const Token& opener) {
        CameraDesc& cam = scene_.camera;  // several camera blocks merge keyword by keyword
        cam.loc = loc(opener);
        open_block();
        read_block(opener, "camera", [&](const Token& k) {
            const std::string_view w = k.text;
            if (w == "eye") {
                cam.eye = vec3(k);
            } else if (w == "look") {
                cam.look = vec3(k);
                cam.use_focus = false;  // the later of look/focus wins
                camera_view_loc_ = loc(k);
            } else if (w == "focus") {
                cam.focus = vec3(k);
                cam.use_focus = true;
                camera_view_loc_ = loc(k);
            } else if (w == "up") {
                cam.up = vec3(k);
                camera_up_loc_ = loc(k);
            } else if (w == "angle") {
                const Token& v = peek();
                cam.angle_deg = number(k);
                if (!(cam.angle_deg > 0 && cam.angle_deg < 180))
                    error(v,
                          "camera 'angle' (full vertical field of view) must be between 0 and "
                          "180 degrees, exclusive; found " +
                              num_str(cam.angle_deg));
            } else if (w == "near-far") {
                cam.near_plane = number(k);
                cam.far_plane = number(k);
            } else {
                unknown_keyword(k, "camera", kCameraKeywords);
            }
        });
    }

    void parse_light(const Token& opener) {
        PendingLight light;
        LightDesc& desc = light.desc;
        desc.loc = loc(opener);
        light.direction_loc = light.function_loc = desc.loc;
        bool has_light_keyword = false, has_ambient = false;
        open_block();
        const bool ok = read_block(opener, "light", [&](const Token& k) {
            const std::string_view w = k.text;
            bool known = true;
            if (w == "type") {
                const Token& t = word(k, "a light type (point, directional or spotlight)");
                light.has_type = true;
                if (t.text == "point")
                    desc.type = LightType::Point;
                else if (t.text == "directional")
                    desc.type = LightType::Directional;
                else if (t.text == "spotlight")
                    desc.type = LightType::Spot;
                else
                    error(t, "unknown light type " + describe(t) + did_you_mean(t.text, kLightTypes) +
                                 " (expected one of: " + kLightTypes + ")");
            } else if (w == "position") {
                desc.position = vec3(k);
                light.has_position = true;
            } else if (w == "direction") {
                desc.direction = vec3(k);
                light.direction_loc = loc(k);
                light.has_direction = true;
            } else if (w == "color") {
                desc.color = vec3(k);
                light.has_color = true;
            } else if (w == "function") {
                desc.falloff = vec3(k);
                light.function_loc = loc(k);
            } else if (w == "aperture") {
                const Token& v = peek();
                desc.aperture_deg = number(k);
                if (!(desc.aperture_deg > 0 && desc.aperture_deg <= 180))
                    error(v,
                          "light 'aperture' (half-angle of the spot cone) must be in (0, 180] "
                          "degrees; found " +
                              num_str(desc.aperture_deg));
            } else if (w == "exponent") {
                const Token& v = peek();
                desc.exponent = number(k);
                if (!(desc.exponent >= 0))
                    error(v, "light 'exponent' must be >= 0; found " + num_str(desc.exponent));
            } else if (w == "number") {
                // Brown/Tufts: the light's identifier (§9.4); it has no effect on the picture.
                mark_dialect(Dialect::BrownTufts, k, "'light [ number ...'");
                number(k);
            } else if (w == "ambient") {
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

    // The lights' dialect-dependent defaults, then their checks (the dialect is known now).
    void finish_lights() {
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

    void parse_mastersubgraph(const Token& opener) {
        const bool ok = mark_dialect(Dialect::Labs, opener, "'mastersubgraph'");
        const Token& name = word(opener, "a name");
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
            if (k.text == "trans")
                parse_trans(k, sg);
            else
                unknown_keyword(k, block, kSubgraphKeywords);
        });
        if (duplicate || !ok) return;
        subgraph_index_.emplace(sg.name, static_cast<int>(scene_.subgraphs.size()));
        scene_.subgraphs.push_back(std::move(sg));
    }

    void parse_trans(const Token& opener, SubgraphDesc& sg) {
        TransDesc trans;
        trans.loc = loc(opener);
        glm::mat4& m = trans.matrix;
        const float time = options_.time;
        open_block();
        read_block(opener, "trans", [&](const Token& k) {
            const std::string_view w = k.text;
            // M = T1 · T2 · … · Tn: each transform multiplies on the right, so the last one
            // written is applied to the object first (scene-format.md §3).
            if (w == "translate") {
                m = m * translation_matrix(vec3(k));
            } else if (w == "scale") {
                m = m * scale_matrix(vec3(k));
            } else if (w == "rotate" || w == "angularrate") {
                // angularrate ax ay az rate: `rotate ax ay az (rate·t)` at scene time t (§9.4).
                const glm::vec3 axis = vec3(k);
                const float amount = number(k);
                const float degrees = w == "rotate" ? amount : amount * time;
                const auto r = rotation_matrix(axis, degrees);
                if (!r)
                    error(k, "'" + std::string(w) + "' axis is zero: expected '" + std::string(w) +
                                 " ax ay az " + (w == "rotate" ? "degrees" : "rate") + "' with a non-zero axis");
                else if (w == "rotate" || time != 0)  // at t = 0 exactly the file without it
                    m = m * *r;
            } else if (w == "velocity") {
                // velocity x y z: `translate t·x t·y t·z` at scene time t (§9.4).
                const glm::vec3 v = vec3(k);
                if (time != 0) m = m * translation_matrix(time * v);
            } else if (w == "matrixRC" || w == "matrixCR") {
                std::array<float, 16> v{};
                for (float& x : v) x = number(k);
                const glm::mat4 given = w == "matrixRC" ? matrix_from_rows(v) : matrix_from_columns(v);
                // Shapes are intersected through the inverse of an affine map: a projective
                // bottom row would be dropped without a word, so it is refused instead.
                if (given[0][3] != 0 || given[1][3] != 0 || given[2][3] != 0 || given[3][3] != 1)
                    error(k, "'" + std::string(w) + "' is not an affine transform: its last row must be "
                             "0 0 0 1, found " + bottom_row(given));
                else
                    m = m * given;
            } else if (w == "object") {
                parse_object(k, trans);
            } else if (w == "subgraph") {
                const Token& name = word(k, "a subgraph name");
                trans.subgraphs.push_back({std::string(name.text), loc(name)});
            } else if (w == "trans") {
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
        sg.children.push_back(std::move(trans));
    }

    // Skips the block of an object that is not drawn, with a warning.
    void skip_object(const Token& opener, const Token& type, const std::string& why) {
        warn(loc(type), why);
        open_block();
        skip_to_block_end(opener, "object");
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
        const std::string_view t = type.text;
        if (t == "cube")
            obj.kind = ShapeKind::Cube;
        else if (t == "cylinder")
            obj.kind = ShapeKind::Cylinder;
        else if (t == "cone")
            obj.kind = ShapeKind::Cone;
        else if (t == "sphere")
            obj.kind = ShapeKind::Sphere;
        else if (t == "ellipsoid")
            obj.kind = ShapeKind::Ellipsoid;
        else if (t == "cactus" || t == "cow")
            return skip_object(opener, type, "object " + describe(type) + " skipped: a special shape of another "
                                              "lab whose geometry did not survive (scene-format.md §9.4)");
        else if (t == "mesh" && brown())
            return skip_object(opener, type, "object 'mesh' skipped: its 'meshfile' is in the Brown/Tufts "
                                              "course's own mesh format, which whitted does not read");
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
        const bool ok = read_block(opener, "object", [&](const Token& k) { parse_material(k, mat); });
        if (ok) trans.objects.push_back(std::move(obj));
    }

    void parse_material(const Token& k, MaterialDesc& mat) {
        const std::string_view w = k.text;
        if (w == "ambient")
            mat.ambient = vec3(k);
        else if (w == "diffuse")
            mat.diffuse = vec3(k);
        else if (w == "specular")
            mat.specular = vec3(k);
        else if (w == "reflect")
            mat.reflect = vec3(k);
        else if (w == "transparent")
            mat.transparent = vec3(k);
        else if (w == "emit")
            mat.emit = vec3(k);
        else if (w == "shine")
            mat.shine = number(k);
        else if (w == "ior") {
            const Token& v = peek();
            mat.ior = number(k);
            if (!(mat.ior > 0)) error(v, "'ior' must be > 0; found " + num_str(mat.ior));
        } else if (w == "texture") {
            TextureRef tex;
            tex.loc = loc(k);
            tex.file = std::string(word(k, "a texture file name").text);
            tex.loose_lookup = brown();
            const Token& u = peek();
            tex.repeat_u = number(k);
            if (!(tex.repeat_u > 0))
                error(u, "texture repeat count u must be > 0; found " + num_str(tex.repeat_u));
            const Token& v = peek();
            tex.repeat_v = number(k);
            if (!(tex.repeat_v > 0))
                error(v, "texture repeat count v must be > 0; found " + num_str(tex.repeat_v));
            mat.texture = std::move(tex);
        } else if (w == "alpha") {
            // An OpenGL opacity some authors wrote (§9.4): read, and ignored with one warning.
            number(k);
            if (!alpha_warned_)
                warn(loc(k), "'alpha' has no effect and is ignored (transparency is 'transparent r g b'); "
                             "this warning is given once per file");
            alpha_warned_ = true;
        } else if (w == "blend" && brown()) {
            const Token& v = peek();
            const float b = number(k);
            if (!(b >= 0 && b <= 1))
                error(v, "'blend' (the texture's share of the diffuse colour) must be in [0, 1]; found " + num_str(b));
            mat.blend = b;
        } else {
            unknown_keyword(k, "object", brown() ? kBrownObjectKeywords : kObjectKeywords);
        }
    }

    // ---- checks that need the whole file ----------------------------------------------------

    void check_whole_file() {
        if (auto d = check_subgraph_references(scene_)) {
            error(d->loc, d->message);
        } else if (auto c = check_subgraph_cycles(scene_)) {
            error(c->loc, c->message);
        }
        const auto root = subgraph_index_.find("root");
        scene_.root = root == subgraph_index_.end() ? -1 : root->second;
        if (scene_.root < 0 && errors_ == 0) {
            // Reported at the top of the file, like an empty one: there is no one place to point at.
            // (After other errors, root may be missing only because its block was misread.)
            std::string defined;
            for (std::size_t i = 0; i < scene_.subgraphs.size() && i < 5; ++i)
                defined += (i ? ", '" : " (it defines '") + scene_.subgraphs[i].name + "'";
            if (scene_.subgraphs.size() > 5) defined += ", ...";
            if (!defined.empty()) defined += ")";
            error(SourceLoc{file_, 1, 1},
                  "no 'mastersubgraph root' in the file" + defined + ": root is the scene and is required");
        }
        if (auto d = check_camera(scene_.camera, camera_up_loc_, camera_view_loc_))
            error(d->loc, d->message);
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
