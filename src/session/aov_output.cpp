#include "session/aov_output.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <set>
#include <sstream>

#include "accel/scene.h"
#include "film/image_io.h"
#include "session/session.h"

namespace whitted {
namespace {

bool is_exr(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".exr";
}

std::string source_of(const Scene& scene, std::uint32_t id) {
    if (id == 0 || id > scene.data.instances.size()) return "background";
    const SourceLoc loc = scene.data.provenance.material_object(scene.data.instances[id - 1].material);
    if (loc.line == 0) return "(no source line)";
    return loc.file + ":" + std::to_string(loc.line);
}

// A colour per id that neighbouring ids do not share (a mixed hash), never dark: the background is black.
glm::u8vec3 id_colour(std::uint32_t id) {
    if (id == 0) return glm::u8vec3(0);
    std::uint32_t h = id * 0x9E3779B1u;
    h ^= h >> 15;
    h *= 0x85EBCA77u;
    h ^= h >> 13;
    return {std::uint8_t(64 + (h & 0xBF)), std::uint8_t(64 + ((h >> 8) & 0xBF)), std::uint8_t(64 + ((h >> 16) & 0xBF))};
}

std::set<std::uint32_t> ids_in(const ImageLayer& object_layer) {
    std::set<std::uint32_t> ids;
    for (float v : object_layer.values) ids.insert(std::uint32_t(v));
    return ids;
}

}  // namespace

std::string aov_png_path(const std::string& base, const std::string& layer) {
    const std::filesystem::path p(base);
    return (p.parent_path() / (p.stem().string() + "." + layer + ".png")).string();
}

std::string object_table(const Scene& scene, const ImageLayer& object_layer) {
    std::ostringstream out;
    for (std::uint32_t id : ids_in(object_layer)) out << id << " " << source_of(scene, id) << "\n";
    return out.str();
}

Image aov_png_image(const Scene& scene, const AovLayer& layer, const ImageLayer& values, int width, int height) {
    Image image(width, height);
    const std::size_t n = values.channels.size(), pixels = std::size_t(width) * std::size_t(height);
    auto grey = [&](float missing) {
        float most = 0.0f;
        for (std::size_t i = 0; i < pixels; ++i)
            if (std::isfinite(values.values[i])) most = std::max(most, values.values[i]);
        for (std::size_t i = 0; i < pixels; ++i) {
            const float v = values.values[i];
            const std::uint8_t b = std::isfinite(v) ? to_byte(most > 0.0f ? v / most : 0.0f) : to_byte(missing);
            std::fill_n(&image.rgb[3 * i], 3, b);
        }
        return most;
    };
    switch (layer.kind) {
        case AovKind::Depth: {
            std::ostringstream max;
            max.precision(9);
            max << grey(1.0f);
            image.text = {{"depth max", max.str()}};
            break;
        }
        case AovKind::Samples: {
            std::ostringstream max;
            max << grey(0.0f);
            image.text = {{"samples max", max.str()}};
            break;
        }
        case AovKind::Object: {
            std::ostringstream table;
            for (std::uint32_t id : ids_in(values)) {
                const glm::u8vec3 c = id_colour(id);
                table << id << " " << int(c.x) << "," << int(c.y) << "," << int(c.z) << " " << source_of(scene, id)
                      << "\n";
            }
            for (std::size_t i = 0; i < pixels; ++i) {
                const glm::u8vec3 c = id_colour(std::uint32_t(values.values[i]));
                image.rgb[3 * i] = c.x, image.rgb[3 * i + 1] = c.y, image.rgb[3 * i + 2] = c.z;
            }
            image.text = {{"objects", table.str()}};
            break;
        }
        case AovKind::Normal:
            for (std::size_t i = 0; i < pixels * n; ++i) image.rgb[i] = to_byte(0.5f * values.values[i] + 0.5f);
            break;
        default:
            for (std::size_t i = 0; i < pixels * n; ++i) image.rgb[i] = to_byte(values.values[i]);
    }
    return image;
}

std::string write_image_with_aovs(const Session& session, const std::string& image_path, const std::string& aov_file,
                                  const ImageText& text) {
    const AovPlan* plan = session.aov_plan();
    const std::string target = aov_file.empty() ? image_path : aov_file;
    const bool one_file = is_exr(target);
    const std::vector<ImageLayer> layers = plan ? plan->resolve(session.aov_film(), session.film()) : std::vector<ImageLayer>{};
    // The image itself, unless it is the file that holds the layers too.
    if (!(plan && one_file && target == image_path)) {
        std::string err;
        if (is_linear_output(image_path)) {
            LinearImage image = session.film().to_linear();
            image.text = text;
            err = write_linear_image(image, image_path);
        } else {
            Image image = session.film().to_image();
            image.text = text;
            err = write_image(image, image_path);
        }
        if (!err.empty() || !plan) return err;
    }
    const int w = session.job().width, h = session.job().height;
    if (one_file) {
        LinearImage image = session.film().to_linear();
        image.text = text;
        for (std::size_t i = 0; i < layers.size(); ++i)
            if (plan->layers()[i].kind == AovKind::Object) image.text.push_back({"objects", object_table(session.scene(), layers[i])});
        return write_linear_image(image, target, layers);
    }
    for (std::size_t i = 0; i < layers.size(); ++i) {
        Image image = aov_png_image(session.scene(), plan->layers()[i], layers[i], w, h);
        image.text.insert(image.text.begin(), text.begin(), text.end());
        if (std::string err = write_image(image, aov_png_path(target, plan->layers()[i].name)); !err.empty()) return err;
    }
    return "";
}

}  // namespace whitted
