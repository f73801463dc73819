#include "compare/explain_variants.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "film/film.h"
#include "integrator/integrator.h"
#include "render/renderer.h"

namespace whitted {
namespace {

struct Named {
    VariantId id;
    const char* name;
    const char* words;
    bool shading;  // a switch of the §7 shading (integrator/conventions.h)
};

constexpr Named kMistakes[] = {
    {VariantId::HorizontalFov, "horizontal-fov", "horizontal field of view", false},
    {VariantId::PixelCorners, "pixel-corners", "rays through pixel corners instead of centres", false},
    {VariantId::UpsideDown, "upside-down", "the image upside down", false},
    {VariantId::NormalsByM, "normals-by-m", "normals transformed by M instead of (M^-1)^T", true},
    {VariantId::BlinnPhong, "blinn-phong", "Blinn-Phong (N.H)^n instead of (R.V)^n", true},
    {VariantId::NoAttenuation, "no-attenuation", "light attenuation ignored", false},
    {VariantId::OpaqueShadows, "opaque-shadows", "shadows opaque instead of tinted by `transparent`", true},
    {VariantId::ShadowsBeyondLight, "shadows-beyond-light", "shadow rays counting hits beyond the light", true},
    {VariantId::DepthMinusOne, "depth-minus-1", "recursion one level shallower (reflections one bounce short)",
     false},
    {VariantId::DepthPlusOne, "depth-plus-1", "recursion one level deeper", false},
    {VariantId::NoTotalInternalReflection, "no-tir", "no total internal reflection", true},
    {VariantId::EtaInverted, "eta-inverted", "the index of refraction inverted (eta = ior going in)", false},
    {VariantId::TextureVFlipped, "texture-v-flipped", "texture v flipped", false},
    {VariantId::NoOffset, "no-offset", "no self-intersection offset (surface acne)", true},
    {VariantId::Gamma, "gamma", "a gamma of 2.2 applied (the spec writes linear values)", false},
};

constexpr Named kRemovals[] = {
    {VariantId::NoSpecular, "no-specular", "no specular term", false},
    {VariantId::NoDiffuse, "no-diffuse", "no diffuse term", false},
    {VariantId::NoAmbient, "no-ambient", "no ambient term", false},
    {VariantId::NoReflection, "no-reflection", "no reflection", false},
    {VariantId::NoTransmission, "no-transmission", "no transmission (glass drawn opaque)", false},
};

const char* removal_term(VariantId id) {
    switch (id) {
        case VariantId::NoSpecular: return "specular";
        case VariantId::NoDiffuse: return "diffuse";
        case VariantId::NoAmbient: return "ambient";
        case VariantId::NoReflection: return "reflection";
        case VariantId::NoTransmission: return "transmission";
        default: return "";
    }
}

// The scene with the variant's change to its data, or none if the variant leaves the data alone.
std::optional<Scene> changed_scene(const Scene& scene, VariantId id) {
    auto with = [&](auto&& change) {
        std::optional<Scene> s(scene);  // the BVHs copied as they are: no geometry changes
        change(s->data);
        return s;
    };
    switch (id) {
        case VariantId::NoAttenuation:
            return with([](SceneData& d) {
                for (Light& l : d.lights) l.falloff = glm::vec3(1, 0, 0);
            });
        case VariantId::EtaInverted:
            return with([](SceneData& d) {
                for (Material& m : d.materials)
                    if (m.ior > 0.0f) m.ior = 1.0f / m.ior;
            });
        case VariantId::TextureVFlipped:
            // Rows flipped: sampling them at v is sampling the file's at 1 − v (texel centres included).
            return with([](SceneData& d) {
                for (TextureImage& t : d.textures)
                    for (int y = 0; y < t.height / 2; ++y)
                        std::swap_ranges(t.rgb.begin() + std::ptrdiff_t(y) * t.width * 3,
                                         t.rgb.begin() + std::ptrdiff_t(y + 1) * t.width * 3,
                                         t.rgb.begin() + std::ptrdiff_t(t.height - 1 - y) * t.width * 3);
            });
        case VariantId::NoSpecular:
            return with([](SceneData& d) {
                for (Material& m : d.materials) m.specular = glm::vec3(0.0f);
            });
        case VariantId::NoDiffuse:
            return with([](SceneData& d) {
                for (Material& m : d.materials) {
                    m.diffuse = glm::vec3(0.0f);
                    if (m.blend >= 0.0f) m.blend = 0.0f;  // the texel's share of a blend is diffuse too
                }
            });
        case VariantId::NoAmbient:
            return with([](SceneData& d) {
                for (Material& m : d.materials) m.ambient = glm::vec3(0.0f);
            });
        case VariantId::NoReflection:
            return with([](SceneData& d) {
                for (Material& m : d.materials) m.reflect = glm::vec3(0.0f);
            });
        case VariantId::NoTransmission:
            return with([](SceneData& d) {
                for (Material& m : d.materials) m.transparent = glm::vec3(0.0f);
            });
        default: return std::nullopt;
    }
}

}  // namespace

std::vector<Variant> explain_variants(const Scene& scene, const RenderJob& job) {
    const bool whitted_shading =
        job.integrator.mode == RenderMode::Whitted && scene.data.lighting == LightingModel::Labs;
    std::vector<Variant> out;
    for (const Named& n : kMistakes)
        if (whitted_shading || !n.shading) out.push_back(Variant{n.id, -1, n.name, n.words, false, ""});
    for (const Named& n : kRemovals) out.push_back(Variant{n.id, -1, n.name, n.words, true, removal_term(n.id)});
    if (whitted_shading) {
        const int lights = int(std::min<std::size_t>(scene.data.lights.size(), kMaxShadowLights));
        for (int k = 0; k < lights; ++k) {
            const std::string number = std::to_string(k + 1);
            out.push_back(Variant{VariantId::NoShadowsFromLight, k, "no-shadows-light-" + number,
                                  "no shadows from light " + number, true, "shadows of light " + number});
        }
    }
    return out;
}

LinearImage render_variant(const Scene& scene, const RenderJob& reference_job, const Variant* variant,
                           bool quantize) {
    RenderJob job = reference_job;
    job.region.reset();
    job.on_tile = nullptr;
    job.active = nullptr;
    Camera camera = job.camera_for(scene);
    std::optional<Scene> changed;
    if (variant) {
        Conventions& c = job.integrator.conventions;
        const float aspect = float(job.width) / float(job.height);
        switch (variant->id) {
            case VariantId::HorizontalFov: camera.tan_half_fov /= aspect; break;
            case VariantId::PixelCorners:
                // through(x − ½, y − ½) is through(x, y) with `forward` moved by half a pixel
                // left and up: tan·aspect / width = tan / height each way.
                camera.forward += camera.tan_half_fov / float(job.height) * (camera.up - camera.right);
                break;
            case VariantId::NormalsByM: c.normals_by_m = true; break;
            case VariantId::BlinnPhong: c.blinn_phong = true; break;
            case VariantId::OpaqueShadows: c.opaque_shadows = true; break;
            case VariantId::ShadowsBeyondLight: c.shadows_beyond_light = true; break;
            case VariantId::DepthMinusOne: job.integrator.max_depth = std::max(0, job.integrator.max_depth - 1); break;
            case VariantId::DepthPlusOne: ++job.integrator.max_depth; break;
            case VariantId::NoTotalInternalReflection: c.no_total_internal_reflection = true; break;
            case VariantId::NoOffset: c.no_offset = true; break;
            case VariantId::NoShadowsFromLight: c.unshadowed_lights = 1u << variant->light; break;
            default: changed = changed_scene(scene, variant->id); break;
        }
    }
    const Scene& drawn = changed ? *changed : scene;
    const auto integrator = make_integrator(drawn, camera, job.integrator);
    Film film(job.width, job.height);
    render(*integrator, job, film);
    LinearImage image = film.to_linear();
    if (variant && variant->id == VariantId::UpsideDown)
        for (int y = 0; y < image.height / 2; ++y)
            std::swap_ranges(image.rgb.begin() + std::ptrdiff_t(y) * image.width,
                             image.rgb.begin() + std::ptrdiff_t(y + 1) * image.width,
                             image.rgb.begin() + std::ptrdiff_t(image.height - 1 - y) * image.width);
    if (variant && variant->id == VariantId::Gamma)
        for (glm::vec3& p : image.rgb) p = glm::pow(glm::max(p, glm::vec3(0.0f)), glm::vec3(1.0f / 2.2f));
    if (quantize)
        for (glm::vec3& p : image.rgb) p = glm::vec3(to_byte(p.x), to_byte(p.y), to_byte(p.z)) / 255.0f;
    return image;
}

}  // namespace whitted
