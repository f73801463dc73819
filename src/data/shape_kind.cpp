#include "data/shape_kind.h"

namespace whitted {

const char* shape_name(ShapeKind kind) {
    switch (kind) {
        case ShapeKind::Cube: return "cube";
        case ShapeKind::Cylinder: return "cylinder";
        case ShapeKind::Cone: return "cone";
        case ShapeKind::Sphere: return "sphere";
        case ShapeKind::Ellipsoid: return "ellipsoid";
        case ShapeKind::Mesh: return "mesh";
    }
    return "?";
}

}  // namespace whitted
