#include "render/aov.h"

#include <algorithm>
#include <charconv>
#include <limits>
#include <utility>

namespace whitted {
namespace {

// A pixel's first floats, whatever the layers: the samples that hit something, then the object of
// the sample nearest the centre (1 once a sample is in; its distance from the centre; its id).
constexpr int kHits = 0, kObjectSet = 1, kObjectDistance = 2, kObjectId = 3, kFixed = 4;

struct Named {
    AovKind kind;
    const char* name;
    bool whitted, path;
};
constexpr Named kNamed[] = {
    {AovKind::Ambient, "ambient", true, false},     {AovKind::Diffuse, "diffuse", true, false},
    {AovKind::Specular, "specular", true, false},   {AovKind::Reflect, "reflect", true, false},
    {AovKind::Transmit, "transmit", true, false},   {AovKind::Emit, "emit", true, false},
    {AovKind::Background, "background", true, false},
    {AovKind::Direct, "direct", false, true},       {AovKind::Indirect, "indirect", false, true},
    {AovKind::Normal, "normal", true, true},        {AovKind::Depth, "depth", true, true},
    {AovKind::Albedo, "albedo", true, true},        {AovKind::Object, "object", true, true},
    {AovKind::Samples, "samples", true, true},
};
struct PerLight {
    AovKind kind;
    const char* prefix;
};
constexpr PerLight kPerLight[] = {
    {AovKind::LightDiffuse, "diffuse.L"}, {AovKind::LightSpecular, "specular.L"}, {AovKind::Shadow, "shadow.L"}};

const char* base_name(AovKind kind) {
    for (const Named& n : kNamed)
        if (n.kind == kind) return n.name;
    for (const PerLight& p : kPerLight)
        if (p.kind == kind) return p.prefix;
    return "";
}

int float_count(AovKind kind) {
    switch (kind) {
        case AovKind::Depth: return 1;
        case AovKind::Object:
        case AovKind::Samples: return 0;  // the fixed floats, the colour film's weights
        default: return 3;
    }
}

// The channels of a layer as Blender and Nuke read them: colours R G B, a normal X Y Z, a
// distance Z (Blender's Depth pass), an id or a count X (as Blender's IndexOB pass).
std::vector<std::string> channel_names(const AovLayer& l) {
    const char* const* letters;
    static const char* const rgb[] = {"R", "G", "B"}, *xyz[] = {"X", "Y", "Z"}, *z[] = {"Z"}, *x[] = {"X"};
    int n = 3;
    switch (l.kind) {
        case AovKind::Normal: letters = xyz; break;
        case AovKind::Depth: letters = z, n = 1; break;
        case AovKind::Object:
        case AovKind::Samples: letters = x, n = 1; break;
        default: letters = rgb;
    }
    std::vector<std::string> out;
    for (int i = 0; i < n; ++i) out.push_back(l.name + "." + letters[i]);
    return out;
}

using Wanted = std::vector<std::pair<AovKind, int>>;

// What `name` asks for in `mode`: adds it to `out`; "" or why not. lights < 0: not known yet.
std::string parse_name(const std::string& name, RenderMode mode, long lights, Wanted& out) {
    const bool whitted = mode == RenderMode::Whitted;
    auto all_lights = [&](AovKind kind) {
        for (long k = 0; k < lights; ++k) out.push_back({kind, int(k)});
    };
    if (name == "all") {
        for (const Named& n : kNamed)
            if (whitted ? n.whitted : n.path) out.push_back({n.kind, -1});
        if (whitted)
            for (const PerLight& p : kPerLight) all_lights(p.kind);
        return "";
    }
    for (const Named& n : kNamed)
        if (name == n.name) {
            if (!(whitted ? n.whitted : n.path))
                return std::string("the layer '") + name + "' is " + (n.whitted ? "Whitted" : "path") + " mode's";
            out.push_back({n.kind, -1});
            return "";
        }
    for (const PerLight& p : kPerLight) {
        const std::string prefix = p.prefix;
        const bool group = name == prefix + "*" || (p.kind == AovKind::Shadow && name == "shadow");
        if (!group && name.rfind(prefix, 0) != 0) continue;
        if (!whitted) return "the layer '" + name + "' is Whitted mode's";
        if (group) {
            all_lights(p.kind);
            return "";
        }
        const std::string digits = name.substr(prefix.size());
        long k = 0;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), k);
        if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || k < 1)
            return "'" + name + "' names no light: L1 is the scene's first light";
        if (lights >= 0 && k > lights)
            return "'" + name + "' names light " + std::to_string(k) + ", and the scene has " +
                   std::to_string(lights) + (lights == 1 ? " light" : " lights");
        out.push_back({p.kind, int(k - 1)});
        return "";
    }
    return "unknown layer '" + name + "' (" + (whitted ? "Whitted" : "path") + " mode's are: " +
           (whitted ? "ambient, diffuse, specular, reflect, transmit, emit, background, diffuse.Lk, specular.Lk, "
                      "shadow.Lk, "
                    : "direct, indirect, ") +
           "normal, depth, albedo, object, samples, all)";
}

std::string mode_problem(RenderMode mode) {
    if (mode == RenderMode::Whitted || mode == RenderMode::Path) return "";
    return std::string("--aov is for whitted and path modes (") + render_mode_name(mode) +
           " mode's image is a single layer already)";
}

}  // namespace

std::vector<std::string> split_aov_list(const std::string& list) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        std::string name = list.substr(start, comma - start);
        name.erase(0, name.find_first_not_of(" \t"));
        name.erase(name.find_last_not_of(" \t") + 1);
        if (!name.empty()) out.push_back(name);
        start = comma + 1;
    }
    return out;
}

std::string check_aov_names(const std::vector<std::string>& names, RenderMode mode) {
    if (std::string p = mode_problem(mode); !p.empty()) return p;
    Wanted ignored;
    for (const std::string& n : names)
        if (std::string p = parse_name(n, mode, -1, ignored); !p.empty()) return p;
    return "";
}

std::string AovPlan::make(const std::vector<std::string>& names, RenderMode mode, std::size_t lights, AovPlan& out) {
    if (std::string p = mode_problem(mode); !p.empty()) return p;
    Wanted wanted;
    for (const std::string& n : names)
        if (std::string p = parse_name(n, mode, long(lights), wanted); !p.empty()) return p;
    std::sort(wanted.begin(), wanted.end());
    wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
    if (wanted.size() > kMaxAovLayers)
        return "--aov asks for " + std::to_string(wanted.size()) + " layers, more than " +
               std::to_string(kMaxAovLayers) + " (name the lights' layers one by one: diffuse.L1,shadow.L2,...)";
    out = AovPlan{};
    out.lights_ = lights;
    int offset = kFixed;
    for (const auto& [kind, light] : wanted) {
        AovLayer l{kind, light, base_name(kind), offset};
        if (light >= 0) l.name += std::to_string(light + 1);
        offset += float_count(kind);
        out.layers_.push_back(std::move(l));
    }
    out.channels_ = offset;
    return "";
}

void AovPlan::add(float* p, const AovSample& s, float centre_distance) const {
    if (s.hit) p[kHits] += 1.0f;
    if (p[kObjectSet] == 0.0f || centre_distance < p[kObjectDistance]) {
        p[kObjectSet] = 1.0f;
        p[kObjectDistance] = centre_distance;
        p[kObjectId] = s.hit ? float(s.instance + 1) : 0.0f;
    }
    auto add3 = [&](int offset, const glm::vec3& v) {
        p[offset] += v.x;
        p[offset + 1] += v.y;
        p[offset + 2] += v.z;
    };
    for (const AovLayer& l : layers_) {
        switch (l.kind) {
            case AovKind::Ambient: add3(l.offset, s.ambient); break;
            case AovKind::Diffuse: add3(l.offset, s.diffuse); break;
            case AovKind::Specular: add3(l.offset, s.specular); break;
            case AovKind::Reflect: add3(l.offset, s.reflect); break;
            case AovKind::Transmit: add3(l.offset, s.transmit); break;
            case AovKind::Emit: add3(l.offset, s.emit); break;
            case AovKind::Background: add3(l.offset, s.background); break;
            case AovKind::LightDiffuse: add3(l.offset, s.light_diffuse[std::size_t(l.light)]); break;
            case AovKind::LightSpecular: add3(l.offset, s.light_specular[std::size_t(l.light)]); break;
            case AovKind::Shadow: add3(l.offset, s.light_shadow[std::size_t(l.light)]); break;
            case AovKind::Direct: add3(l.offset, s.direct); break;
            case AovKind::Indirect: add3(l.offset, s.indirect); break;
            case AovKind::Normal: add3(l.offset, s.normal); break;
            case AovKind::Albedo: add3(l.offset, s.albedo); break;
            case AovKind::Depth: p[l.offset] += s.hit ? s.depth : 0.0f; break;
            case AovKind::Object:
            case AovKind::Samples: break;
        }
    }
}

std::uint32_t AovPlan::object_id(const ChannelFilm& aov, int x, int y) {
    return std::uint32_t(aov.at(x, y)[kObjectId]);
}

std::vector<ImageLayer> AovPlan::resolve(const ChannelFilm& aov, const Film& film) const {
    const int w = aov.width(), h = aov.height();
    const PixelRegion r = aov.region();
    std::vector<ImageLayer> out;
    for (const AovLayer& l : layers_) {
        ImageLayer layer;
        layer.channels = channel_names(l);
        const std::size_t n = layer.channels.size();
        layer.values.assign(std::size_t(w) * std::size_t(h) * n, 0.0f);
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) {
                const float* p = aov.at(x, y);
                const float samples = film.at(x, y).weight, hits = p[kHits];
                float* v = &layer.values[(std::size_t(y) * std::size_t(w) + std::size_t(x)) * n];
                switch (l.kind) {
                    case AovKind::Object: v[0] = p[kObjectId]; break;
                    case AovKind::Samples: v[0] = samples; break;
                    case AovKind::Depth:
                        v[0] = hits > 0.0f ? p[l.offset] / hits : std::numeric_limits<float>::infinity();
                        break;
                    case AovKind::Normal:
                    case AovKind::Albedo:
                        for (std::size_t c = 0; c < 3; ++c) v[c] = hits > 0.0f ? p[l.offset + int(c)] / hits : 0.0f;
                        break;
                    default:
                        for (std::size_t c = 0; c < 3; ++c) v[c] = samples > 0.0f ? p[l.offset + int(c)] / samples : 0.0f;
                }
            }
        out.push_back(std::move(layer));
    }
    return out;
}

}  // namespace whitted
