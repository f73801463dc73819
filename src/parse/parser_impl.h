#pragma once
// The parser's insides, shared by parser.cpp (tokens, diagnostics, framing, the file level and the
// whole-file checks) and parse_blocks.cpp (the blocks' keywords). Not an interface: use parser.h.
#include "parse/parser.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "parse/binary_sniff.h"
#include "parse/falloff.h"
#include "parse/lexer.h"
#include "parse/number.h"
#include "parse/scene_checks.h"
#include "parse/suggest.h"
#include "base/transforms.h"

namespace whitted::parse_detail {

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
constexpr const char* kCameraKeywords = "eye, look, focus, up, angle, near-far, aperture, focaldistance";
constexpr const char* kLightKeywords =
    "type, position, direction, color, function, aperture, exponent, radius, angle, ambient, number";
constexpr const char* kLightTypes = "point, directional, spotlight";
constexpr const char* kSubgraphKeywords = "trans";
constexpr const char* kTransKeywords =
    "translate, scale, rotate, matrixRC, matrixCR, velocity, angularrate, object, subgraph";
constexpr const char* kObjectKeywords =
    "ambient, diffuse, specular, reflect, transparent, emit, shine, ior, gloss, texture, alpha, file";
constexpr const char* kBrownObjectKeywords =
    "ambient, diffuse, specular, reflect, transparent, emit, shine, ior, gloss, texture, alpha, blend";
constexpr const char* kShapeNames = "cube, cylinder, cone, sphere, ellipsoid, mesh";
// Shapes of other labs whose geometry did not survive (§9.4): skipped with a warning.
constexpr const char* kLostShapes = "cactus, cow";
constexpr const char* kAllShapeWords = "cube, cylinder, cone, sphere, ellipsoid, cactus, cow, mesh";

// Whether `word` is one of the comma-separated words of `list`.
inline bool in_list(std::string_view word, std::string_view list) {
    while (!list.empty()) {
        const std::size_t end = list.find(',');
        if (list.substr(0, end) == word) return true;
        if (end == std::string_view::npos) break;
        list.remove_prefix(std::min(list.size(), end + 2));  // ", "
    }
    return false;
}

// A token as it should appear in a message: quoted, printable, not absurdly long.
inline std::string describe(const Token& t) {
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

inline std::string pos_str(const Token& t) { return std::to_string(t.line) + ":" + std::to_string(t.col); }

inline std::string num_str(float v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

// A light as written, with what it left out: the Brown/Tufts dialect gives the missing words
// other meanings (§9.4), and the dialect is known only once the whole file has been read.
struct PendingLight {
    LightDesc desc;
    bool has_type = false, has_position = false, has_direction = false, has_color = false;
    SourceLoc direction_loc, function_loc, radius_loc, angle_loc;
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
    SourceLoc camera_up_loc_, camera_view_loc_, camera_aperture_loc_;  // line 0 until written
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
        } else if (peek().kind == TokenKind::Word && pos_ + 1 < tokens_.size() &&
                   tokens_[pos_ + 1].kind == TokenKind::Open &&
                   parse_number(peek().text).status == NumberStatus::Invalid &&
                   !in_list(peek().text, expected)) {
            // `object cube [ … ]` where it does not belong: the word and its block go with it (one
            // error, not a second one for 'cube').
            const Token& word = next();
            next();
            skip_to_block_end(word, "'" + std::string(word.text) + "'");
            skipped = " and " + describe(word) + " with its bracketed block";
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
            else if (std::string_view(expected) == kSubgraphKeywords && in_list(keyword.text, kTransKeywords))
                error(keyword, describe(keyword) + " cannot stand directly" + where +
                                   ": it belongs inside a 'trans [ ... ]' block");
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
                implicit_root_->implicit = true;
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
            implicit_root_->implicit = true;
        }
        SubgraphDesc discarded;  // read on to find the file's other errors, then dropped
        parse_trans(t, ok ? *implicit_root_ : discarded);
    }

    void parse_background(const Token& opener);
    void parse_camera(const Token& opener);
    void parse_light(const Token& opener);
    // The lights' dialect-dependent defaults, then their checks (the dialect is known now).
    void finish_lights();
    void parse_mastersubgraph(const Token& opener);
    void parse_trans(const Token& opener, SubgraphDesc& sg);
    // Skips the block of an object that is not drawn, with a warning.
    void skip_object(const Token& opener, const Token& type, const std::string& why);
    void parse_object(const Token& opener, TransDesc& trans);
    void parse_material(const Token& k, MaterialDesc& mat);

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
        const CameraDesc& cam = scene_.camera;
        if (cam.aperture > 0 && !cam.use_focus && !(cam.focal_distance > 0))
            error(camera_aperture_loc_, "camera 'aperture' " + num_str(cam.aperture) +
                                            " needs a distance to focus at: give 'focaldistance F', or a 'focus' "
                                            "point (the camera looks along 'look', so there is none)");
    }
};

}  // namespace whitted::parse_detail
