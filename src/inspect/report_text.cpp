#include "inspect/report_text.h"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "integrator/whitted_integrator.h"

namespace whitted {
namespace {

std::string num(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4f", double(v));
    return buf;
}

std::string vec(const glm::vec3& v) { return num(v.x) + " " + num(v.y) + " " + num(v.z); }
std::string paren(const glm::vec3& v) {
    std::string s = "(";  // appended, not "(" + …: GCC 12 warns falsely (-Wrestrict) on that form
    s += vec(v);
    s += ")";
    return s;
}

const char* light_type_name(LightType t) {
    switch (t) {
        case LightType::Point: return "point";
        case LightType::Directional: return "directional";
        case LightType::Spot: return "spot";
    }
    return "?";
}

std::string object_text(const ObjectInfo& o, const std::string& base) {
    return std::string(shape_name(o.kind)) + " at " + display_loc(o.loc, base);
}

void write_parts(std::ostream& out, const PixelReport& r) {
    const ColourParts& p = r.parts;
    auto line = [&](const char* name, const glm::vec3& v, bool always) {
        if (always || v != glm::vec3(0.0f)) out << "  " << name << vec(v) << "\n";
    };
    line("ambient      ", p.ambient, true);
    line("diffuse      ", p.diffuse, true);
    line("specular     ", p.specular, true);
    line("reflect      ", p.reflect, true);
    line("transparent  ", p.transparent, true);
    line("emit         ", p.emit, true);
    line("background   ", p.background, false);
    line("clamped      ", p.clamp, false);
}

void write_secondary(std::ostream& out, const char* name, const SecondaryInfo& s, const PixelReport& r,
                     const std::string& base) {
    using Outcome = SecondaryRecord::Outcome;
    out << name << ": ";
    switch (s.record.outcome) {
        case Outcome::NoRay:
            out << (r.depth_limit ? "none (max depth reached)" : "none") << "\n";
            return;
        case Outcome::TooWeak: out << "not traced: its weight " << paren(s.record.weight) << " is below 1/256\n"; return;
        case Outcome::OffSurface: out << "carries nothing: its glossy direction fell below the surface\n"; return;
        case Outcome::RayLimit:
            out << "not traced: the sample had traced its limit of " << kMaxSecondaryRays
                << " reflected and refracted rays\n";
            return;
        case Outcome::Traced: break;
    }
    if (s.next)
        out << "hits " << object_text(s.next->object, base) << " (t " << num(s.next->t) << ", point "
            << paren(s.next->point) << ")";
    else
        out << "leaves the scene (background)";
    out << ", brings " << paren(s.record.color) << ", adds " << paren(s.record.contribution) << "\n";
}

void write_light(std::ostream& out, std::size_t i, const LightInfo& l, const std::string& base) {
    out << "light " << (i + 1) << " (" << light_type_name(l.type) << " at " << display_loc(l.loc, base) << "): ";
    const LightTerm& t = l.term;
    if (!t.faces) {
        out << "no light here (the surface faces away, or the point is outside its cone or reach)\n";
        return;
    }
    const bool blocked = t.shadow == glm::vec3(0.0f);
    const bool tinted = !blocked && t.shadow != glm::vec3(1.0f);
    out << (blocked ? "in shadow" : tinted ? "through glass, shadow " + paren(t.shadow) : std::string("lit"));
    out << ", n.l " << num(t.n_dot_l) << ", intensity " << paren(t.sample.intensity);
    if (!blocked) out << ", diffuse " << paren(t.diffuse) << ", specular " << paren(t.specular);
    out << "\n";
    for (const Blocker& b : l.blockers)
        out << "  " << (b.transparent ? "through " : "shadowed by ") << object_text(b.object, base) << " (distance "
            << num(b.t) << ")\n";
}

}  // namespace

std::string display_path(const std::string& file, const std::string& base_dir) {
    if (base_dir.empty() || file.empty()) return file;
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path f = fs::absolute(fs::path(file), ec).lexically_normal();
    const fs::path b = fs::absolute(fs::path(base_dir), ec).lexically_normal();
    if (ec) return file;
    const fs::path rel = f.lexically_relative(b);
    if (rel.empty() || *rel.begin() == "..") return file;
    return rel.string();
}

std::string display_loc(const SourceLoc& loc, const std::string& base_dir) {
    if (loc.line <= 0) return "(not from a file)";
    return display_path(loc.file, base_dir) + ":" + std::to_string(loc.line) + ":" + std::to_string(loc.col);
}

namespace {

void write_report(std::ostream& out, const PixelReport& r, const std::string& base);

}  // namespace

std::string report_text(const PixelReport& r, const std::string& base) {
    std::ostringstream out;
    write_report(out, r, base);
    out << ray_tree_text(r.ray_tree, base);
    return out.str();
}

namespace {

void write_report(std::ostream& out, const PixelReport& r, const std::string& base) {
    out << "pixel " << r.x << "," << r.y << " of " << r.width << "x" << r.height << ": " << render_mode_name(r.mode)
        << " mode, max depth " << r.max_depth << ", " << r.samples << (r.samples == 1 ? " sample" : " samples")
        << " (aa " << r.sampling.aa << ", spp " << r.sampling.spp
        << (r.sampling.adaptive() ? ", adaptive " + num(r.sampling.aa_threshold) : std::string()) << ")\n";
    out << "colour " << vec(r.value) << " = bytes " << int(r.bytes.x) << " " << int(r.bytes.y) << " "
        << int(r.bytes.z) << "\n";
    if (r.decomposed)
        write_parts(out, r);
    else
        out << "  (not split into parts: " << r.note << ")\n";

    const int total = r.samples > 0 ? r.samples : 1;
    if (total > 1) {
        out << "samples:";
        const char* sep = " ";
        for (const SeenCount& s : r.seen) {
            out << sep << (s.background ? std::string("background") : object_text(s.object, base))
                << " in " << s.samples << " of " << total;
            sep = ", ";
        }
        out << "\ndetail: sample " << r.detail_sample << " (the one nearest the pixel's centre)\n";
    }
    out << "camera ray: from " << paren(r.camera_ray.origin) << " direction " << paren(r.camera_ray.direction) << "\n";
    if (!r.hit) {
        out << "background: the camera ray hits nothing; the background colour is " << paren(r.background) << "\n";
        return;
    }
    const HitInfo& h = *r.hit;
    out << "object: " << object_text(h.object, base) << "\n";
    for (const ChainLink& l : h.object.chain)
        out << "  in " << link_keyword(l.kind) << (l.name.empty() ? "" : " " + l.name) << " at "
            << display_loc(l.loc, base) << "\n";
    const Material& m = r.material;
    out << "material: ambient " << vec(m.ambient) << ", diffuse " << vec(m.diffuse) << ", specular "
        << vec(m.specular) << ", shine " << num(m.shine) << ", reflect " << vec(m.reflect) << ", transparent "
        << vec(m.transparent) << ", ior " << num(m.ior) << ", emit " << vec(m.emit);
    if (m.gloss > 0.0f) out << ", gloss " << num(m.gloss);
    if (!r.texture_file.empty())
        out << ", texture \"" << r.texture_file << "\" repeat " << num(m.repeat_u) << " " << num(m.repeat_v);
    if (m.blend >= 0.0f) out << ", blend " << num(m.blend);
    out << "\n";
    if (m.texture >= 0)
        out << "  with the texel: diffuse " << vec(r.diffuse_at_hit) << ", ambient " << vec(r.ambient_at_hit) << "\n";
    out << "hit: t " << num(h.t) << ", point " << paren(h.point) << ", normal " << paren(h.normal) << ", uv ("
        << num(h.uv.x) << " " << num(h.uv.y) << ")" << (h.outside ? "" : ", from inside the shape") << "\n";
    if (r.lights.empty()) out << "lights: none\n";
    for (std::size_t i = 0; i < r.lights.size(); ++i) write_light(out, i, r.lights[i], base);
    if (r.total_internal_reflection)
        out << "total internal reflection: the transparent weight goes to the reflected ray\n";
    write_secondary(out, "reflected ray", r.reflected, r, base);
    write_secondary(out, "refracted ray", r.refracted, r, base);
}

}  // namespace

}  // namespace whitted
