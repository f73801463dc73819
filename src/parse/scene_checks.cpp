#include "parse/scene_checks.h"

#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace whitted {
namespace {

Diagnostic error_at(const SourceLoc& loc, std::string message) {
    return Diagnostic{Severity::Error, loc, std::move(message)};
}

std::string vec_str(const glm::vec3& v) {
    std::ostringstream s;
    s << v.x << ' ' << v.y << ' ' << v.z;
    return s.str();
}

struct Edge {
    int target;
    const SubgraphRef* ref;
};

}  // namespace

std::optional<Diagnostic> check_subgraph_references(const SceneDescription& scene) {
    const SubgraphIndex index = index_subgraphs(scene);
    for (const auto& sg : scene.subgraphs)
        for (const auto& trans : sg.children)
            for (const auto& ref : trans.subgraphs)
                if (!index.count(ref.name))
                    return error_at(ref.loc, "undefined subgraph '" + ref.name +
                                                 "': no 'mastersubgraph " + ref.name +
                                                 "' in this file");
    return std::nullopt;
}

std::optional<Diagnostic> check_subgraph_cycles(const SceneDescription& scene) {
    const int n = static_cast<int>(scene.subgraphs.size());
    const SubgraphIndex index = index_subgraphs(scene);
    std::vector<std::vector<Edge>> edges(n);
    for (int i = 0; i < n; ++i)
        for (const auto& trans : scene.subgraphs[i].children)
            for (const auto& ref : trans.subgraphs) {
                const auto target = index.find(ref.name);
                if (target != index.end()) edges[i].push_back({target->second, &ref});
            }

    // Iterative depth-first search (a long chain of subgraphs must not overflow the stack).
    enum Color : unsigned char { White, Gray, Black };
    std::vector<Color> color(n, White);
    std::vector<std::pair<int, size_t>> stack;  // node, next edge to follow
    for (int start = 0; start < n; ++start) {
        if (color[start] != White) continue;
        stack.push_back({start, 0});
        color[start] = Gray;
        while (!stack.empty()) {
            auto& [node, next] = stack.back();
            if (next == edges[node].size()) {
                color[node] = Black;
                stack.pop_back();
                continue;
            }
            const Edge edge = edges[node][next++];
            if (color[edge.target] == White) {
                color[edge.target] = Gray;
                stack.push_back({edge.target, 0});
            } else if (color[edge.target] == Gray) {  // back edge: the cycle is on the stack
                size_t first = 0;
                while (stack[first].first != edge.target) ++first;
                // Long cycles are shortened to their first and last names: still findable.
                const size_t length = stack.size() - first, head = 8, tail = 4;
                std::string path;
                for (size_t k = first; k < stack.size(); ++k) {
                    const size_t i = k - first;
                    if (length > head + tail && i == head)
                        path += "... (" + std::to_string(length - head - tail) + " more) -> ";
                    if (length > head + tail && i >= head && i < length - tail) continue;
                    path += scene.subgraphs[stack[k].first].name + " -> ";
                }
                path += scene.subgraphs[edge.target].name;
                return error_at(edge.ref->loc, "subgraph cycle: " + path);
            }
        }
    }
    return std::nullopt;
}

std::optional<Diagnostic> check_camera(const CameraDesc& camera, const SourceLoc& up_loc,
                                       const SourceLoc& view_loc) {
    const glm::dvec3 view(camera.view_direction());
    const glm::dvec3 up(camera.up);
    const SourceLoc& at_view = view_loc.line > 0 ? view_loc : camera.loc;
    const SourceLoc& at_up = up_loc.line > 0 ? up_loc : camera.loc;
    if (!(glm::length(view) > 1e-12))
        return error_at(at_view, camera.use_focus ? "camera 'focus' " + vec_str(camera.focus) +
                                                        " equals 'eye': there is no view direction"
                                                  : "camera 'look' direction is zero");
    if (!(glm::length(up) > 1e-12)) return error_at(at_up, "camera 'up' vector is zero");
    const double sine = glm::length(glm::cross(glm::normalize(view), glm::normalize(up)));
    if (!(sine > 1e-6))
        return error_at(at_up, "camera 'up' " + vec_str(camera.up) +
                                   " is parallel to the view direction " +
                                   vec_str(camera.view_direction()));
    return std::nullopt;
}

}  // namespace whitted
