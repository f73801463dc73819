#pragma once
// Builds small render-ready scenes in code, without the parser, for tests of later stages.
#include <glm/gtc/matrix_transform.hpp>

#include "accel/scene.h"
#include "flatten/flatten.h"

namespace whitted::test {

class SceneBuilder {
public:
    SceneBuilder() { flat_.ambient_intensity = glm::vec3(1.0f); }

    // Places a unit shape with the object-to-world matrix m.
    SceneBuilder& add(ShapeKind kind, const glm::mat4& m, const Material& material) {
        flat_.instances.push_back(make_instance(m, kind, std::uint32_t(flat_.materials.size())));
        flat_.materials.push_back(material);
        return *this;
    }
    SceneBuilder& light(const Light& l) { flat_.lights.push_back(l); return *this; }
    SceneBuilder& background(glm::vec3 c) { flat_.background = c; return *this; }
    SceneBuilder& ambient(glm::vec3 c) { flat_.ambient_intensity = c; return *this; }
    Scene build() { return accelerate(flat_); }

private:
    SceneData flat_;
};

inline glm::mat4 translate_scale(glm::vec3 t, glm::vec3 s) {
    return glm::scale(glm::translate(glm::mat4(1.0f), t), s);
}

// A material that only glows: no lighting terms, so a test can see exactly which rays reach it.
inline Material emitter(glm::vec3 e) {
    Material m;
    m.diffuse = glm::vec3(0.0f);
    m.emit = e;
    return m;
}

inline Light point_light(glm::vec3 position, glm::vec3 color, glm::vec3 falloff = {1, 0, 0}) {
    Light l;
    l.type = LightType::Point;
    l.position = position;
    l.color = color;
    l.falloff = falloff;
    return l;
}

}  // namespace whitted::test
