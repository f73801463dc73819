#pragma once
// Reading one JSON object of a scene file against what it may hold: every key checked (an unknown
// one is an error, with "did you mean"), required keys asked for, values of the wrong type or size
// refused, each problem at the key or value it is about. Problems are collected, not thrown: the
// reader goes on and reports every one of a file's errors at once.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "base/diagnostic.h"
#include "cs1230/json_tree.h"

namespace whitted::cs1230 {

// Errors listed (the rest only counted), as for the bracket format; warnings kept (the rest counted).
constexpr std::size_t kMaxErrors = 20, kMaxWarnings = 1000;

// The file being read and where its problems go.
struct Context {
    Context(const JsonTree& t, const LineIndex& l, std::string p, std::vector<Diagnostic>& d)
        : tree(t), lines(l), path(std::move(p)), diagnostics(d) {}
    const JsonTree& tree;
    const LineIndex& lines;
    std::string path;
    std::vector<Diagnostic>& diagnostics;
    // A file of a million bad values must not make a million messages: past a few hundred, the
    // problems are counted (finish() keeps the first kMaxErrors in file order, then a count).
    std::size_t errors = 0, warnings = 0;
    bool lenient = false;  // unknown keys are warnings (--lenient)
    std::vector<Diagnostic> unlisted_errors;  // beyond the first few hundred: only the earliest one kept

    SourceLoc at(std::uint32_t offset) const;
    void error(std::uint32_t offset, std::string message) { report(Severity::Error, offset, std::move(message)); }
    void warning(std::uint32_t offset, std::string message) { report(Severity::Warning, offset, std::move(message)); }
    void report(Severity severity, std::uint32_t offset, std::string message);
    // Sorts the diagnostics into file order, keeps the first kMaxErrors errors and says how many more.
    void finish();
};

class Fields {
public:
    // The object at `node`, called `what` in messages ("cameraData", "a light"), may hold the keys
    // `allowed`. A node that is not an object is an error here, and the reads below find nothing.
    Fields(Context& ctx, std::uint32_t node, std::string what, std::vector<std::string_view> allowed);

    bool ok() const { return object_; }
    std::uint32_t offset() const;  // of the object's `{`
    const std::string& what() const { return what_; }

    // An error for each key not allowed; a warning for a key written twice (the later one counts).
    void check_keys();
    // An error at the `{` unless `key` is there.
    bool require(std::string_view key);

    // The value of `key` (its last occurrence), or null when absent.
    const JsonTree::Node* get(std::string_view key) const;
    // The same as an index into the tree's nodes.
    std::optional<std::uint32_t> node_of(std::string_view key) const;
    std::uint32_t key_offset(std::string_view key) const;  // of its key, or of the `{` when absent
    bool has(std::string_view key) const { return get(key) != nullptr; }
    // The keys present other than `except`, in the order written.
    std::vector<const JsonTree::Member*> members_except(std::string_view except) const;

    // Typed reads: true with `out` set when `key` is present and of the right type; false when it
    // is absent (no error) or wrong (an error at the value). Numbers must fit a 32-bit float.
    bool number(std::string_view key, float& out);
    bool vec3(std::string_view key, glm::vec3& out);
    bool vec4(std::string_view key, glm::vec4& out);
    bool string(std::string_view key, std::string& out);
    // Rows of four numbers, row by row (`matrix`): out[column][row], glm's order.
    bool matrix(std::string_view key, glm::mat4& out);
    // An array (of anything): its items' nodes.
    bool array(std::string_view key, std::vector<std::uint32_t>& items);

private:
    bool numbers(std::string_view key, const JsonTree::Node& value, float* out, int n, const char* shape);
    bool finite_float(std::string_view key, const JsonTree::Node& value, float& out);

    Context& ctx_;
    std::uint32_t node_;
    std::string what_;
    std::vector<std::string_view> allowed_;
    bool object_ = false;
};

}  // namespace whitted::cs1230
