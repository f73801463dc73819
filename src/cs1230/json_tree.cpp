#include "cs1230/json_tree.h"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <new>

#include <nlohmann/json.hpp>

namespace whitted::cs1230 {
namespace {

// Watches the characters nlohmann's lexer takes, in order (it takes each exactly once: a
// character it looks ahead at and puts back is not taken again), to know where the token behind
// each SAX event began: the opening quote of the last string, the first character of the last
// number or literal, the last character taken (a bracket, for the structural events).
struct Tracker {
    const char* begin = nullptr;
    std::uint32_t last = 0;          // the last character taken
    std::uint32_t string_start = 0;  // the last string's opening quote
    std::uint32_t scalar_start = 0;  // the last number's or literal's first character
    std::uint32_t token_start = 0;   // the start of the last token of any kind
    bool in_string = false, escape = false, in_scalar = false;

    void take(const char* p) {
        const char c = *p;
        last = std::uint32_t(p - begin);
        if (in_string) {
            if (escape) escape = false;
            else if (c == '\\') escape = true;
            else if (c == '"') in_string = false;
            return;
        }
        switch (c) {
            case '"':
                in_string = true;
                string_start = token_start = last;
                in_scalar = false;
                break;
            case ' ': case '\t': case '\n': case '\r':
                in_scalar = false;
                break;
            case ',': case ':': case '[': case ']': case '{': case '}':
                token_start = last;
                in_scalar = false;
                break;
            default:  // a number's or literal's character (or a stray one the lexer will refuse)
                if (!in_scalar) scalar_start = token_start = last;
                in_scalar = true;
        }
    }
};

// A forward iterator over the text that tells the tracker of every character taken.
class TrackingIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    TrackingIterator() = default;
    TrackingIterator(const char* p, Tracker* t) : p_(p), t_(t) {}
    reference operator*() const { return *p_; }
    TrackingIterator& operator++() {
        t_->take(p_);
        ++p_;
        return *this;
    }
    TrackingIterator operator++(int) {
        TrackingIterator old = *this;
        ++*this;
        return old;
    }
    bool operator==(const TrackingIterator& o) const { return p_ == o.p_; }
    bool operator!=(const TrackingIterator& o) const { return p_ != o.p_; }

private:
    const char* p_ = nullptr;
    Tracker* t_ = nullptr;
};

using json = nlohmann::json;

// Builds the tree from the SAX events. A container's children wait on `pending_` until it
// closes, then move to the tree's arrays together (so that they are contiguous there).
class TreeBuilder {
public:
    TreeBuilder(JsonParseResult& out, const Tracker& tracker, std::uint32_t text_size)
        : out_(out), tree_(out.tree), tracker_(tracker), text_size_(text_size) {}

    bool null() { return scalar(JsonTree::Kind::Null, tracker_.scalar_start); }
    bool boolean(bool b) {
        if (!scalar(JsonTree::Kind::Bool, tracker_.scalar_start)) return false;
        tree_.nodes.back().boolean = b;
        return true;
    }
    bool number_integer(json::number_integer_t v) { return number(double(v)); }
    bool number_unsigned(json::number_unsigned_t v) { return number(double(v)); }
    bool number_float(json::number_float_t v, const std::string&) { return number(v); }
    bool string(std::string& s) {
        if (!scalar(JsonTree::Kind::String, tracker_.string_start)) return false;
        tree_.nodes.back().first = intern(std::move(s));
        return true;
    }
    bool binary(json::binary_t&) { return fail("binary values are not JSON", tracker_.token_start); }
    bool start_object(std::size_t) { return open(JsonTree::Kind::Object); }
    bool key(std::string& k) {
        frames_.back().key = intern(std::move(k));
        frames_.back().key_offset = tracker_.string_start;
        return true;
    }
    bool end_object() { return close(); }
    bool start_array(std::size_t) { return open(JsonTree::Kind::Array); }
    bool end_array() { return close(); }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
        // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error while …":
        // the part after the position (ours is given as FILE:LINE:COL).
        std::string what = e.what();
        if (const auto colon = what.find(": "); colon != std::string::npos) what = what.substr(colon + 2);
        // At the start of the token the lexer gave up on (it may have read on into the next one).
        if (what.find("end of input") != std::string::npos) return fail(what, text_size_);
        if (what.find("invalid string") != std::string::npos) return fail(what, tracker_.string_start);
        if (what.find("invalid literal") != std::string::npos || what.find("invalid number") != std::string::npos)
            return fail(what, tracker_.scalar_start);
        return fail(what, tracker_.token_start);
    }

private:
    struct Frame {
        std::uint32_t node;
        std::size_t pending_start;  // its children's entries on pending_
        std::uint32_t key = 0, key_offset = 0;  // an object's current key
    };

    bool fail(const std::string& why, std::uint32_t offset) {
        if (out_.error.empty()) {
            out_.error = why;
            out_.error_offset = offset;
        }
        return false;
    }
    std::uint32_t intern(std::string&& s) {
        tree_.strings.push_back(std::move(s));
        return std::uint32_t(tree_.strings.size() - 1);
    }
    bool number(double v) {
        if (!scalar(JsonTree::Kind::Number, tracker_.scalar_start)) return false;
        tree_.nodes.back().number = v;
        return true;
    }
    std::uint32_t add_node(JsonTree::Kind kind, std::uint32_t offset) {
        JsonTree::Node n;
        n.kind = kind;
        n.offset = offset;
        tree_.nodes.push_back(n);
        return std::uint32_t(tree_.nodes.size() - 1);
    }
    // A finished value goes to its container (or is the document).
    void attach(std::uint32_t value) {
        if (frames_.empty()) {
            tree_.root = value;
            return;
        }
        const Frame& f = frames_.back();
        pending_.push_back({f.key, f.key_offset, value});
    }
    bool scalar(JsonTree::Kind kind, std::uint32_t offset) {
        attach(add_node(kind, offset));
        return true;
    }
    bool open(JsonTree::Kind kind) {
        if (frames_.size() >= std::size_t(kMaxJsonDepth))
            return fail("arrays and objects nested more than " + std::to_string(kMaxJsonDepth) + " deep",
                        tracker_.last);
        frames_.push_back({add_node(kind, tracker_.last), pending_.size()});
        return true;
    }
    bool close() {
        const Frame f = frames_.back();
        frames_.pop_back();
        JsonTree::Node& n = tree_.nodes[f.node];
        const std::size_t count = pending_.size() - f.pending_start;
        if (n.kind == JsonTree::Kind::Array) {
            n.first = std::uint32_t(tree_.items.size());
            for (std::size_t i = f.pending_start; i < pending_.size(); ++i) tree_.items.push_back(pending_[i].value);
        } else {
            n.first = std::uint32_t(tree_.members.size());
            tree_.members.insert(tree_.members.end(), pending_.begin() + std::ptrdiff_t(f.pending_start), pending_.end());
        }
        n.count = std::uint32_t(count);
        pending_.resize(f.pending_start);
        attach(f.node);
        return true;
    }

    JsonParseResult& out_;
    JsonTree& tree_;
    const Tracker& tracker_;
    std::uint32_t text_size_;
    std::vector<Frame> frames_;
    std::vector<JsonTree::Member> pending_;  // arrays use only `value`
};

}  // namespace

JsonParseResult parse_json(std::string_view text) {
    JsonParseResult out;
    if (text.size() > 0xffffffffu) {
        out.error = "the file is too large (more than 4 GiB)";
        return out;
    }
    Tracker tracker;
    tracker.begin = text.data();
    TreeBuilder builder(out, tracker, std::uint32_t(text.size()));
    try {
        out.ok = json::sax_parse(TrackingIterator(text.data(), &tracker),
                                 TrackingIterator(text.data() + text.size(), &tracker), &builder,
                                 json::input_format_t::json, /*strict=*/true, /*ignore_comments=*/false);
    } catch (const std::bad_alloc&) {
        throw;  // the caller reports running out of memory as it does for every stage
    } catch (const std::exception& e) {
        if (out.error.empty()) {
            out.error = e.what();
            out.error_offset = tracker.token_start;
        }
        out.ok = false;
    }
    if (!out.ok && out.error.empty()) out.error = "not a JSON document";
    if (!out.ok) out.tree = JsonTree{};
    return out;
}

LineIndex::LineIndex(std::string_view text) {
    starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') starts_.push_back(std::uint32_t(i + 1));
}

void LineIndex::locate(std::uint32_t offset, int& line, int& col) const {
    const auto it = std::upper_bound(starts_.begin(), starts_.end(), offset);
    const std::size_t l = std::size_t(it - starts_.begin());  // ≥ 1: starts_[0] = 0 ≤ offset
    line = int(l);
    col = int(offset - starts_[l - 1]) + 1;
}

const char* describe_kind(JsonTree::Kind kind) {
    switch (kind) {
        case JsonTree::Kind::Null: return "null";
        case JsonTree::Kind::Bool: return "true or false";
        case JsonTree::Kind::Number: return "a number";
        case JsonTree::Kind::String: return "a string";
        case JsonTree::Kind::Array: return "an array";
        case JsonTree::Kind::Object: return "an object";
    }
    return "?";
}

}  // namespace whitted::cs1230
