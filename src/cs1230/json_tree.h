#pragma once
// JSON text → a compact tree whose every value and key knows where it starts in the text, so that
// a scene's errors can be reported at the key or value they are about (FILE:LINE:COL). The
// grammar is nlohmann/json's (strict RFC 8259: no comments, no trailing commas, UTF-8 checked);
// this only adds the positions, which its SAX interface does not give.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace whitted::cs1230 {

// Nesting of arrays and objects beyond this is refused: the scene reader walks the tree recursively.
constexpr int kMaxJsonDepth = 256;

struct JsonTree {
    enum class Kind : unsigned char { Null, Bool, Number, String, Array, Object };
    struct Node {
        Kind kind = Kind::Null;
        bool boolean = false;
        std::uint32_t offset = 0;  // byte offset of the value's first character
        // String: `first` indexes `strings`. Array: items[first, first + count). Object:
        // members[first, first + count), in the order written.
        std::uint32_t first = 0, count = 0;
        double number = 0;
    };
    struct Member {
        std::uint32_t key;         // into `strings`
        std::uint32_t key_offset;  // of the key's opening quote
        std::uint32_t value;       // into `nodes`
    };
    std::vector<Node> nodes;  // nodes[root] is the document
    std::vector<std::uint32_t> items;
    std::vector<Member> members;
    std::vector<std::string> strings;
    std::uint32_t root = 0;

    const Node& node(std::uint32_t i) const { return nodes[i]; }
    const std::string& text(const Node& n) const { return strings[n.first]; }
    const std::string& key(const Member& m) const { return strings[m.key]; }
};

struct JsonParseResult {
    JsonTree tree;
    bool ok = false;
    std::string error;            // when !ok: what is wrong ("syntax error while parsing …")
    std::uint32_t error_offset = 0;  // where (may be text.size(): the end of the text)
};

// Parses `text` (at most 4 GiB) into a tree; on a syntax error, the first error and where it is.
JsonParseResult parse_json(std::string_view text);

// Line and column (both from 1; columns in bytes, a tab counting one) of byte offsets in a text.
class LineIndex {
public:
    explicit LineIndex(std::string_view text);
    void locate(std::uint32_t offset, int& line, int& col) const;

private:
    std::vector<std::uint32_t> starts_;  // offset of each line's first byte
};

// "a number", "a string", "an array", …: what a value is, for messages.
const char* describe_kind(JsonTree::Kind kind);

}  // namespace whitted::cs1230
