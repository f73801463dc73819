#include "description/scene_description.h"

namespace whitted {

const char* dialect_name(Dialect dialect) {
    switch (dialect) {
        case Dialect::Labs: break;
        case Dialect::BrownTufts: return "Brown/Tufts";
        case Dialect::Cs1230: return "Brown CSCI 1230 (JSON)";
    }
    return "SceneView/Ray labs";
}

SubgraphIndex index_subgraphs(const SceneDescription& scene) {
    SubgraphIndex index;
    for (std::size_t i = 0; i < scene.subgraphs.size(); ++i) index.emplace(scene.subgraphs[i].name, int(i));
    return index;
}

int find_subgraph(const SubgraphIndex& index, std::string_view name) {
    const auto it = index.find(name);
    return it == index.end() ? -1 : it->second;
}

int SceneDescription::find_subgraph(const std::string& name) const {
    for (size_t i = 0; i < subgraphs.size(); ++i)
        if (subgraphs[i].name == name) return static_cast<int>(i);
    return -1;
}

}  // namespace whitted
