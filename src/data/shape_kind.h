#pragma once
// What a placed object is: one of the unit shapes of scene-format.md §4 (and §9.4's ellipsoid), or
// a triangle mesh. Shared by the file's description, the render-ready data and the intersectors.

namespace whitted {

// Ellipsoid: x² + 4y² + z² = 1 (scene-format.md §9.4), the only unit shape reaching outside the unit cube.
// Mesh: a triangle mesh from an OBJ file (§9.3), not a unit shape; the unit-shape code never sees it.
enum class ShapeKind : unsigned char { Cube = 0, Cylinder = 1, Cone = 2, Sphere = 3, Ellipsoid = 4, Mesh = 5 };
const char* shape_name(ShapeKind kind);

}  // namespace whitted
