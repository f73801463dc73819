#include "scene/scene_description.h"

namespace whitted {

const char* shape_name(ShapeKind kind) {
    switch (kind) {
        case ShapeKind::Cube: return "cube";
        case ShapeKind::Cylinder: return "cylinder";
        case ShapeKind::Cone: return "cone";
        case ShapeKind::Sphere: return "sphere";
    }
    return "?";
}

int SceneDescription::find_subgraph(const std::string& name) const {
    for (size_t i = 0; i < subgraphs.size(); ++i)
        if (subgraphs[i].name == name) return static_cast<int>(i);
    return -1;
}

}  // namespace whitted
