#include "cs1230/json_fields.h"

#include <cfloat>
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <unordered_set>

#include "parse/suggest.h"

namespace whitted::cs1230 {
namespace {

std::string in_quotes(std::string_view s) {
    std::string q = "'";  // appended: GCC 12 warns falsely (-Wrestrict) on "'" + std::string(…)
    q += s;
    q += '\'';
    return q;
}

std::string number_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace

SourceLoc Context::at(std::uint32_t offset) const {
    SourceLoc loc;
    loc.file = path;
    lines.locate(offset, loc.line, loc.col);
    return loc;
}

void Context::report(Severity severity, std::uint32_t offset, std::string message) {
    // Errors are kept until there are many more than will be listed: the reader does not visit the
    // file strictly in order, so the first kMaxErrors in file order are among the first few hundred.
    constexpr std::size_t kKeptErrors = 20 * kMaxErrors;
    if (severity == Severity::Error && ++errors > kKeptErrors) {
        const SourceLoc loc = at(offset);
        if (unlisted_errors.empty() || loc.line < unlisted_errors[0].loc.line ||
            (loc.line == unlisted_errors[0].loc.line && loc.col < unlisted_errors[0].loc.col))
            unlisted_errors.assign(1, {severity, loc, std::move(message)});
        return;
    }
    if (severity == Severity::Warning && ++warnings > kMaxWarnings) return;
    diagnostics.push_back({severity, at(offset), std::move(message)});
}

void Context::finish() {
    auto before = [](const Diagnostic& a, const Diagnostic& b) {
        return a.loc.line != b.loc.line ? a.loc.line < b.loc.line : a.loc.col < b.loc.col;
    };
    std::stable_sort(diagnostics.begin(), diagnostics.end(), before);
    std::vector<Diagnostic> kept;
    std::size_t listed = 0;
    const Diagnostic* first_unlisted = unlisted_errors.empty() ? nullptr : &unlisted_errors[0];
    for (const Diagnostic& d : diagnostics) {
        if (d.severity == Severity::Error && ++listed > kMaxErrors) {
            if (!first_unlisted || before(d, *first_unlisted)) first_unlisted = &d;
            continue;
        }
        kept.push_back(d);
    }
    if (errors > kMaxErrors)
        kept.push_back({Severity::Error, first_unlisted->loc,
                        std::to_string(errors - kMaxErrors) + " more error" + (errors - kMaxErrors == 1 ? "" : "s") +
                            " not listed (the first of them is here)"});
    if (warnings > kMaxWarnings)
        kept.push_back({Severity::Warning, kept.empty() ? at(0) : kept.back().loc,
                        std::to_string(warnings - kMaxWarnings) + " more warnings not listed"});
    diagnostics = std::move(kept);
}

Fields::Fields(Context& ctx, std::uint32_t node, std::string what, std::vector<std::string_view> allowed)
    : ctx_(ctx), node_(node), what_(std::move(what)), allowed_(std::move(allowed)) {
    const JsonTree::Node& n = ctx_.tree.node(node_);
    object_ = n.kind == JsonTree::Kind::Object;
    if (!object_) ctx_.error(n.offset, what_ + " must be an object ({ … }), not " + describe_kind(n.kind));
}

std::uint32_t Fields::offset() const { return ctx_.tree.node(node_).offset; }

void Fields::check_keys() {
    if (!object_) return;
    const JsonTree::Node& n = ctx_.tree.node(node_);
    std::string candidates;
    for (std::string_view a : allowed_) {
        if (!candidates.empty()) candidates += ", ";
        candidates += a;
    }
    std::unordered_set<std::string_view> seen;
    for (std::uint32_t i = 0; i < n.count; ++i) {
        const JsonTree::Member& m = ctx_.tree.members[n.first + i];
        const std::string& key = ctx_.tree.key(m);
        bool known = false;
        for (std::string_view a : allowed_) known = known || a == key;
        if (!known) {
            const std::string hint = did_you_mean(key, candidates);
            ctx_.report(ctx_.lenient ? Severity::Warning : Severity::Error, m.key_offset,
                        "unknown key " + in_quotes(key) + " in " + what_ +
                            (hint.empty() ? " (it may hold: " + candidates + ")" : hint) +
                            (ctx_.lenient ? ": skipped (--lenient)" : ""));
            continue;
        }
        if (!seen.insert(key).second)
            ctx_.warning(m.key_offset, in_quotes(key) + " is given twice in " + what_ +
                                           ": this later one counts, as in the course's reader");
    }
}

bool Fields::require(std::string_view key) {
    if (!object_) return false;
    if (has(key)) return true;
    ctx_.error(offset(), what_ + " has no " + in_quotes(key) + ", which it needs");
    return false;
}

const JsonTree::Node* Fields::get(std::string_view key) const {
    if (!object_) return nullptr;
    const JsonTree::Node& n = ctx_.tree.node(node_);
    for (std::uint32_t i = n.count; i-- > 0;) {
        const JsonTree::Member& m = ctx_.tree.members[n.first + i];
        if (ctx_.tree.key(m) == key) return &ctx_.tree.node(m.value);
    }
    return nullptr;
}

std::optional<std::uint32_t> Fields::node_of(std::string_view key) const {
    if (const JsonTree::Node* v = get(key)) return std::uint32_t(v - ctx_.tree.nodes.data());
    return std::nullopt;
}

std::uint32_t Fields::key_offset(std::string_view key) const {
    if (object_) {
        const JsonTree::Node& n = ctx_.tree.node(node_);
        for (std::uint32_t i = n.count; i-- > 0;) {
            const JsonTree::Member& m = ctx_.tree.members[n.first + i];
            if (ctx_.tree.key(m) == key) return m.key_offset;
        }
    }
    return offset();
}

std::vector<const JsonTree::Member*> Fields::members_except(std::string_view except) const {
    std::vector<const JsonTree::Member*> out;
    if (!object_) return out;
    const JsonTree::Node& n = ctx_.tree.node(node_);
    for (std::uint32_t i = 0; i < n.count; ++i) {
        const JsonTree::Member& m = ctx_.tree.members[n.first + i];
        if (ctx_.tree.key(m) != except) out.push_back(&m);
    }
    return out;
}

bool Fields::finite_float(std::string_view key, const JsonTree::Node& value, float& out) {
    if (value.kind != JsonTree::Kind::Number) {
        ctx_.error(value.offset, in_quotes(key) + " in " + what_ + " must hold numbers, not " + describe_kind(value.kind));
        return false;
    }
    if (!(std::abs(value.number) <= double(FLT_MAX))) {
        ctx_.error(value.offset, in_quotes(key) + " in " + what_ + ": " + number_text(value.number) +
                                     " is beyond the range of a 32-bit float");
        return false;
    }
    out = float(value.number);
    return true;
}

bool Fields::number(std::string_view key, float& out) {
    const JsonTree::Node* v = get(key);
    if (!v) return false;
    if (v->kind != JsonTree::Kind::Number) {
        ctx_.error(v->offset, in_quotes(key) + " in " + what_ + " must be a number, not " + describe_kind(v->kind));
        return false;
    }
    return finite_float(key, *v, out);
}

bool Fields::numbers(std::string_view key, const JsonTree::Node& value, float* out, int n, const char* shape) {
    if (value.kind != JsonTree::Kind::Array || value.count != std::uint32_t(n)) {
        std::string found = describe_kind(value.kind);
        if (value.kind == JsonTree::Kind::Array)
            found = "an array of " + std::to_string(value.count) + (value.count == 1 ? " value" : " values");
        ctx_.error(value.offset, in_quotes(key) + " in " + what_ + " must be " + shape + ", not " + found);
        return false;
    }
    bool ok = true;
    for (int i = 0; i < n; ++i) ok = finite_float(key, ctx_.tree.node(ctx_.tree.items[value.first + std::uint32_t(i)]), out[i]) && ok;
    return ok;
}

bool Fields::vec3(std::string_view key, glm::vec3& out) {
    const JsonTree::Node* v = get(key);
    float f[3];
    if (!v || !numbers(key, *v, f, 3, "an array of 3 numbers")) return false;
    out = glm::vec3(f[0], f[1], f[2]);
    return true;
}

bool Fields::vec4(std::string_view key, glm::vec4& out) {
    const JsonTree::Node* v = get(key);
    float f[4];
    if (!v || !numbers(key, *v, f, 4, "an array of 4 numbers")) return false;
    out = glm::vec4(f[0], f[1], f[2], f[3]);
    return true;
}

bool Fields::string(std::string_view key, std::string& out) {
    const JsonTree::Node* v = get(key);
    if (!v) return false;
    if (v->kind != JsonTree::Kind::String) {
        ctx_.error(v->offset, in_quotes(key) + " in " + what_ + " must be a string, not " + describe_kind(v->kind));
        return false;
    }
    out = ctx_.tree.text(*v);
    return true;
}

bool Fields::matrix(std::string_view key, glm::mat4& out) {
    const JsonTree::Node* v = get(key);
    if (!v) return false;
    const char* shape = "4 rows of 4 numbers";
    if (v->kind != JsonTree::Kind::Array || v->count != 4) {
        ctx_.error(v->offset, in_quotes(key) + " in " + what_ + " must be " + shape + ", not " +
                                  (v->kind == JsonTree::Kind::Array ? std::to_string(v->count) + " rows"
                                                                    : std::string(describe_kind(v->kind))));
        return false;
    }
    bool ok = true;
    for (std::uint32_t r = 0; r < 4; ++r) {
        float row[4];
        if (!numbers(key, ctx_.tree.node(ctx_.tree.items[v->first + r]), row, 4, "4 rows of 4 numbers")) {
            ok = false;
            continue;
        }
        for (int c = 0; c < 4; ++c) out[c][int(r)] = row[c];
    }
    return ok;
}

bool Fields::array(std::string_view key, std::vector<std::uint32_t>& items) {
    const JsonTree::Node* v = get(key);
    if (!v) return false;
    if (v->kind != JsonTree::Kind::Array) {
        ctx_.error(v->offset, in_quotes(key) + " in " + what_ + " must be an array ([ … ]), not " + describe_kind(v->kind));
        return false;
    }
    items.assign(ctx_.tree.items.begin() + v->first, ctx_.tree.items.begin() + v->first + v->count);
    return true;
}

}  // namespace whitted::cs1230
