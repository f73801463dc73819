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
#include "parse/keywords.h"
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
// Thrown when nothing more can be read (end of file inside a block) or the parse is cancelled:
// ends the parse.
struct ParseAbort {};

// Errors listed in full; past this many, only counted (a cascade helps nobody).
constexpr int kMaxErrors = 20;
// The cancel flag is looked at after each this many bytes of text (a fraction of a millisecond).
constexpr std::size_t kCancelCheckBytes = std::size_t(64) << 10;

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
            parse_file();
        } catch (const ParseAbort&) {
            // Recorded already; nothing after it can be read.
        }
        if (cancelled_) {  // no verdict on a file not read to its end
            result.cancelled = true;
            return result;
        }
        if (!aborted_) check_whole_file();
        finish_diagnostics();
        result.diagnostics = std::move(diags_);
        result.unlisted_warnings = warnings_ - listed_warnings_;
        if (!has_errors(result.diagnostics)) result.scene = std::move(scene_);
        return result;
    }

private:
    std::string_view text_;
    Lexer lexer_{text_};
    // The next token (peek()) once it has been read, and then possibly the one after it.
    Token current_, ahead_;
    bool has_current_ = false, has_ahead_ = false;
    std::size_t next_cancel_check_ = 0;  // offset in the text
    const std::string& file_;
    ParseOptions options_;
    std::vector<Diagnostic> diags_;
    int errors_ = 0;            // recorded or not
    SourceLoc first_unlisted_;  // of the first error past kMaxErrors
    std::size_t warnings_ = 0, listed_warnings_ = 0;  // given, and kept in diags_
    std::pair<int, int> last_listed_at_;              // line, col of the last listed once there are enough
    bool aborted_ = false, cancelled_ = false;
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
    // Tokens are read when asked for, with a lookahead of two, so they are values: a reference
    // into current_ changes meaning at the next next(). End repeats forever.

    // Whether the cancel flag was looked at recently enough (else: look, and end the parse if set).
    bool cancel_checked() const { return lexer_.offset() < next_cancel_check_; }
    void check_cancel() {
        if (cancel_checked()) return;
        if (options_.cancel && options_.cancel->load(std::memory_order_relaxed)) {
            cancelled_ = true;
            throw ParseAbort{};
        }
        next_cancel_check_ = lexer_.offset() + kCancelCheckBytes;
    }
    Token lex() {
        check_cancel();
        return lexer_.next();
    }
    const Token& peek() {
        if (!has_current_) {
            current_ = lex();
            has_current_ = true;
        }
        return current_;
    }
    // The token after peek().
    const Token& peek_second() {
        if (!has_ahead_) {
            ahead_ = peek().kind == TokenKind::End ? current_ : lex();
            has_ahead_ = true;
        }
        return ahead_;
    }
    Token next() {
        const Token t = peek();
        advance();
        return t;
    }
    // Past peek().
    void advance() {
        if (peek().kind == TokenKind::End) return;
        if (has_ahead_) current_ = ahead_;
        has_current_ = has_ahead_;
        has_ahead_ = false;
    }
    SourceLoc loc(const Token& t) const { return {file_, t.line, t.col}; }

    // Records an error and goes on (the tokens are in a known state).
    void error(const SourceLoc& at, std::string message) {
        if (++errors_ <= kMaxErrors)
            diags_.push_back({Severity::Error, at, std::move(message)});
        else if (errors_ == kMaxErrors + 1)
            first_unlisted_ = at;
    }
    void error(const Token& at, std::string message) {
        if (errors_ > kMaxErrors) {  // past the first unlisted one (whose place is kept): only counted
            ++errors_;
            return;
        }
        error(loc(at), std::move(message));
    }
    // Records an error and unwinds to the innermost block, which skips to its end.
    [[noreturn]] void fail(const SourceLoc& at, std::string message) {
        error(at, std::move(message));
        throw ParseStop{};
    }
    [[noreturn]] void fail(const Token& at, std::string message) {
        fail(loc(at), std::move(message));
    }
    // Only the kMaxWarningsListed first warnings in position order (ties in the order given) are
    // kept, the rest counted, so that a file of a million stray brackets costs no memory for them.
    void warn(const SourceLoc& at, std::string message) {
        ++warnings_;
        if (!lists_warning_at(at.line, at.col)) return;
        if (listed_warnings_ == kMaxWarningsListed) {  // it takes the place of the last one
            diags_.erase(diags_.begin() + static_cast<std::ptrdiff_t>(last_listed_warning()));
            --listed_warnings_;
        }
        diags_.push_back({Severity::Warning, at, std::move(message)});
        if (++listed_warnings_ == kMaxWarningsListed) {
            const SourceLoc& last = diags_[last_listed_warning()].loc;
            last_listed_at_ = {last.line, last.col};
        }
    }
    // Whether a warning at line:col would be listed.
    bool lists_warning_at(int line, int col) const {
        return listed_warnings_ < kMaxWarningsListed || std::pair(line, col) < last_listed_at_;
    }
    // The listed warning that comes last in position order (of those at one position, the last given).
    std::size_t last_listed_warning() const {
        std::size_t last = diags_.size();
        for (std::size_t i = 0; i < diags_.size(); ++i)
            if (diags_[i].severity == Severity::Warning &&
                (last == diags_.size() ||
                 std::pair(diags_[i].loc.line, diags_[i].loc.col) >= std::pair(diags_[last].loc.line, diags_[last].loc.col)))
                last = i;
        return last;
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
    // too, with a warning, since it often means the brackets around it do not match. `where()`
    // says where it is; it is called only for a warning that is listed.
    template <class Where>
    void skip_stray_opens(Where&& where) {
        if (peek().kind == TokenKind::Open) [[unlikely]]
            warn_stray_opens(where);
    }
    template <class Where>
    [[gnu::noinline]] void warn_stray_opens(Where& where) {
        while (peek().kind == TokenKind::Open) {
            const Token t = next();
            if (lists_warning_at(t.line, t.col))
                warn(loc(t), "'[' " + std::string(where()) +
                                 " opens no block and is ignored ('[' belongs after "
                                 "a block keyword such as 'trans' or 'object TYPE')");
            else
                ++warnings_;
        }
    }

    [[noreturn]] void fail_unclosed(const Token& opener, std::string_view block) {
        error(peek(), "unexpected end of file: " + std::string(block) + " block opened at " + pos_str(opener) +
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
        float value;
        if (!has_current_ && cancel_checked() && lexer_.read_plain_number(value)) return value;
        skip_stray_opens([&] { return "among the numbers of '" + std::string(keyword.text) + "'"; });
        const Token& t = peek();
        if (t.kind != TokenKind::Word) fail_not_number(keyword, t);
        const NumberParse n = parse_number(t.text);
        if (n.status != NumberStatus::Ok) [[unlikely]]
            number_problem(keyword, t, n.status);
        advance();
        return n.value;
    }
    // A number that is not Ok: an error (thrown), or a warning.
    void number_problem(const Token& keyword, const Token& t, NumberStatus status) {
        switch (status) {
            case NumberStatus::Invalid: fail_not_number(keyword, t);
            case NumberStatus::OutOfRange:
                fail(t, "number " + describe(t) + " for '" + std::string(keyword.text) +
                            "' is out of range");
            case NumberStatus::TrailingComma:
                warn(loc(t), "trailing ',' after number " + describe(t) + " ignored");
                break;
            case NumberStatus::Ok: break;
        }
    }

    [[noreturn]] void fail_not_number(const Token& keyword, const Token& t) {
        fail(t, "expected a number for '" + std::string(keyword.text) + "', found " + describe(t));
    }

    glm::vec3 vec3(const Token& keyword) {
        const float x = number(keyword);
        const float y = number(keyword);
        const float z = number(keyword);
        return {x, y, z};
    }

    // A name or file name after `keyword` (any word).
    Token word(const Token& keyword, const char* what) {
        skip_stray_opens([&] { return "after '" + std::string(keyword.text) + "'"; });
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

    // The next keyword of a block into `keyword`, or false at its closing `]`.
    bool next_in_block(const Token& opener, std::string_view block, Token& keyword) {
        skip_stray_opens([&] { return "in " + std::string(block) + " block opened at " + pos_str(opener); });
        keyword = next();
        switch (keyword.kind) {
            case TokenKind::Close: return false;
            case TokenKind::End: fail_unclosed(opener, block);
            case TokenKind::Open:  // skipped above
            case TokenKind::Word: break;
        }
        return true;
    }

    // Skips to the `]` that closes a block whose opening (if any) is already consumed.
    void skip_to_block_end(const Token& opener, std::string_view block) {
        int depth = 1;
        while (depth > 0) {
            const Token t = next();
            if (t.kind == TokenKind::End) fail_unclosed(opener, block);
            if (t.kind == TokenKind::Open) ++depth;
            if (t.kind == TokenKind::Close) --depth;
        }
    }

    // Reads a block's keywords up to its `]`, handing each to `on_keyword`. After an error in
    // one of them, the rest of the block is skipped (error recovery); returns false then.
    template <class OnKeyword>
    bool read_block(const Token& opener, std::string_view block, OnKeyword&& on_keyword) {
        Token k;
        while (next_in_block(opener, block, k)) {
            try {
                on_keyword(k);
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
    void unknown_keyword(const Token& keyword, std::string_view block, const char* expected,
                         const char* suggestions = nullptr) {
        // What goes with it: its bracketed block, a word and its block, or the numbers after it.
        enum { Nothing, Block, WordAndBlock, Numbers } skipped = Nothing;
        Token word;
        int count = 0;
        if (peek().kind == TokenKind::Open) {
            next();
            skip_to_block_end(keyword, "'" + std::string(keyword.text) + "'");
            skipped = Block;
        } else if (peek().kind == TokenKind::Word && peek_second().kind == TokenKind::Open &&
                   parse_number(peek().text).status == NumberStatus::Invalid &&
                   !in_list(peek().text, expected)) {
            // `object cube [ … ]` where it does not belong: the word and its block go with it (one
            // error, not a second one for 'cube').
            word = next();
            next();
            skip_to_block_end(word, "'" + std::string(word.text) + "'");
            skipped = WordAndBlock;
        } else {
            while (peek().kind == TokenKind::Word &&
                   parse_number(peek().text).status != NumberStatus::Invalid) {
                next();
                ++count;
            }
            if (count > 0) skipped = Numbers;
        }
        // Past the listed ones only counted, with no message made (a file of a million unknown
        // words would spend seconds on them).
        if (options_.lenient ? !lists_warning_at(keyword.line, keyword.col) : errors_ >= kMaxErrors) {
            options_.lenient ? void(++warnings_) : error(keyword, std::string());
            return;
        }
        const bool is_number = parse_number(keyword.text).status != NumberStatus::Invalid;
        const std::string where = " in " + std::string(block) + " block";
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
        std::string what_else;
        if (skipped == Block)
            what_else = " and its bracketed block";
        else if (skipped == WordAndBlock)
            what_else = " and " + describe(word) + " with its bracketed block";
        else if (skipped == Numbers)
            what_else = " and the " + std::to_string(count) + (count == 1 ? " number after it" : " numbers after it");
        warn(loc(keyword), std::string("skipped ") + (is_number ? "unexpected number " : "unknown keyword ") +
                               describe(keyword) + what_else + where + " (lenient mode)");
    }

    // ---- the grammar ------------------------------------------------------------------------

    void parse_file() {
        if (peek().kind == TokenKind::End)
            fail_empty();
        while (true) {
            skip_stray_opens([] { return "at top level"; });
            if (peek().kind == TokenKind::End) break;
            const Token t = next();
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
        switch (find_keyword(t.text)) {
            case Keyword::Background: return parse_background(t);
            case Keyword::Camera: return parse_camera(t);
            case Keyword::Light: return parse_light(t);
            case Keyword::Mastersubgraph: return parse_mastersubgraph(t);
            case Keyword::Trans: return parse_top_level_trans(t);
            default: return unknown_keyword(t, "top-level", kTopKeywords, kTopWords);
        }
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
    void parse_material(const Token& k, Keyword w, MaterialDesc& mat);

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
