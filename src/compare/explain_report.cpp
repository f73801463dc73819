#include "compare/explain_report.h"

#include <cmath>
#include <cstdio>

#include "compare/report.h"
#include "inspect/report_text.h"

namespace whitted {
namespace {

constexpr double kTermTolerance = 0.1;  // a fitted coefficient this close to 1 is the reference's term
constexpr double kFitExplains = 0.5;    // a fit explaining less than this share names no term
constexpr double kTermShare = 0.05;     // a term named makes at least this share of the difference

std::string fmt(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string db(double psnr) { return std::isinf(psnr) ? std::string("inf dB (identical)") : fmt("%.1f dB", psnr); }

std::string vec(const glm::vec3& v) { return fmt("%.3f", v.x) + " " + fmt("%.3f", v.y) + " " + fmt("%.3f", v.z); }

std::string jnum(double v) { return std::isfinite(v) ? fmt("%.6g", v) : std::string("null"); }
std::string jvec(const glm::vec3& v) {
    std::string s = "[";  // appended, not "[" + …: GCC 12 warns falsely (-Wrestrict) on that form
    s += jnum(v.x) + ", " + jnum(v.y) + ", " + jnum(v.z) + "]";
    return s;
}

std::string object_words(const PixelReport& r, const std::string& base) {
    if (!r.hit) return "the background";
    return std::string(shape_name(r.hit->object.kind)) + " at " + display_loc(r.hit->object.loc, base);
}

// The centre pixel's parts in the reference, the non-zero ones.
std::string parts_words(const PixelReport& r) {
    if (!r.decomposed) return r.note;
    const ColourParts& p = r.parts;
    std::string s;
    auto part = [&](const char* name, const glm::vec3& v) {
        if (glm::all(glm::lessThan(glm::abs(v), glm::vec3(5e-4f)))) return;  // 0.000 as printed
        if (!s.empty()) s += ", ";
        s += std::string(name) + " " + vec(v);
    };
    part("ambient", p.ambient);
    part("diffuse", p.diffuse);
    part("specular", p.specular);
    part("reflect", p.reflect);
    part("transparent", p.transparent);
    part("emit", p.emit);
    part("background", p.background);
    part("clamped", p.clamp);
    return s.empty() ? "all zero" : s;
}

std::string lights_words(const PixelReport& r) {
    std::string s;
    for (std::size_t i = 0; i < r.lights.size(); ++i) {
        const LightTerm& t = r.lights[i].term;
        if (!s.empty()) s += ", ";
        s += "light " + std::to_string(i + 1) + " ";
        s += !t.faces                          ? "faces away"
             : t.shadow == glm::vec3(0.0f)    ? "shadowed"
             : t.shadow == glm::vec3(1.0f)    ? "lit"
                                              : "through glass";
    }
    return s.empty() ? "no lights" : s;
}

}  // namespace

std::string term_words(const TermFit& fit) {
    const double c = fit.coefficient;
    if (std::abs(c - 1.0) < kTermTolerance) return "";
    const bool missing = c < 0.2, weak = c < 1.0;
    const std::string& t = fit.variant.term;
    if (fit.variant.id == VariantId::NoShadowsFromLight) {
        const std::string light = "light " + std::to_string(fit.variant.light + 1) + "'s shadows are ";
        return light + (missing ? "missing" : weak ? "too light" : "too dark");
    }
    const char* how = missing ? "missing" : weak ? "too weak" : "too strong";
    if (t == "specular") return std::string("the specular highlights are ") + how;
    if (t == "diffuse") return std::string("the diffuse shading is ") + how;
    if (t == "ambient") return std::string("the ambient term is ") + how;
    if (t == "reflection") return std::string("the reflections are ") + how;
    if (t == "transmission") return std::string("what shows through transparent objects is ") + how;
    return t + " is " + how;
}

std::string region_fit_words(const Region& g) {
    if (g.terms.empty()) return "no term of the reference shows in these pixels";
    if (g.explained < kFitExplains)
        return "the terms explain " + fmt("%.0f%%", 100.0 * g.explained) + " of the difference: another kind of mistake";
    std::string s;
    for (const TermFit& t : g.terms)
        if (const std::string words = term_words(t); !words.empty() && t.share >= kTermShare)
            s += (s.empty() ? "" : "; ") + words + " (" + fmt("%.2f", t.coefficient) + " x the reference's " +
                 t.variant.term + ")";
    return (s.empty() ? "no single term is off by 10% or more" : s) + " (the fit explains " +
           fmt("%.0f%%", 100.0 * g.explained) + ")";
}

std::string explain_summary(const Explanation& e) {
    if (!e.differs()) return "no difference";
    std::string s;
    if (!e.matches.empty()) {
        const VariantMatch& m = e.matches.front();
        s = "looks like: " + m.variant.words + " (" + (std::isinf(m.psnr) ? std::string("identical") : db(m.psnr)) +
            " against " + db(e.psnr) + " as is)";
    }
    if (e.explained >= kFitExplains)
        for (const TermFit& t : e.terms)
            if (const std::string words = term_words(t); !words.empty() && t.share >= kTermShare) {
                s += (s.empty() ? "" : "; ") + words;
                break;
            }
    return s.empty() ? "no named mistake or term" : s;
}

std::string explain_text(const ExplainInputs& in, const ExplainOptions& o, const Explanation& e) {
    const CompareReport& r = e.compare;
    std::string s = "whitted explain: " + in.image_path + " (" + in.image_format + ") against whitted's render of " +
                    in.scene_path + " (" + std::to_string(r.width) + "x" + std::to_string(r.height) + ")\n";
    if (!e.differs()) {
        s += "no difference: PSNR " + db(e.psnr) + ", largest channel difference " + fmt("%.4g", r.errors.max_error) +
             "\n";
        return s + verdict_name(r.verdict) + "\n";
    }
    s += "differs: " + std::to_string(e.differing) + " of " + std::to_string(r.errors.pixels) + " pixels (" +
         fmt("%.1f%%", 100.0 * double(e.differing) / double(std::max<std::size_t>(1, r.errors.pixels))) +
         ") by more than " + fmt("%.3g", std::max(o.differ, o.compare.thresholds.warn)) + "; PSNR " + db(e.psnr) +
         ", FLIP mean " + fmt("%.3f", r.flip.mean) + ", worst " + std::to_string(o.compare.ssim.block) + "x" +
         std::to_string(o.compare.ssim.block) + " SSIM " + fmt("%.3f", r.ssim.worst.ssim) + "\n";

    s += "\nWhich convention (the image against the lab's classic mistakes, each rendered by whitted):\n";
    if (e.matches.empty()) {
        s += "  none matches far better than the reference (by " + fmt("%.0f", o.better_db) + " dB)";
        for (const VariantMatch& m : e.variants)
            if (m.changes_scene) {
                s += "; the closest: " + m.variant.name + " at " + db(m.psnr) + ", against " + db(e.psnr) + " as is";
                break;
            }
        s += "\n";
    }
    for (const VariantMatch& m : e.matches)
        s += "  your image matches whitted with *" + m.variant.words + "* (" + m.variant.name + ") at " + db(m.psnr) +
             ", against " + db(e.psnr) + " as is\n";

    s += "\nWhich term (the difference over the differing pixels fitted as a sum of the reference's terms):\n";
    if (e.terms.empty()) {
        s += "  no term of the reference shows in the differing pixels\n";
    } else {
        // A poor fit's coefficients are whatever soaks up another kind of difference: not named.
        int said = 0;
        for (const TermFit& t : e.terms)
            if (const std::string words = term_words(t);
                !words.empty() && e.explained >= kFitExplains && t.share >= kTermShare) {
                s += "  " + words + ": your image has " + fmt("%.2f", t.coefficient) + " x the reference's " +
                     t.variant.term + (t.variant.id == VariantId::NoShadowsFromLight ? "" : " term") + " (" +
                     fmt("%.0f%%", 100.0 * t.share) + " of the difference)\n";
                ++said;
            }
        if (said == 0 && e.explained >= kFitExplains)
            s += "  no single term makes 5% of the difference or is off by 10% or more\n";
        s += "  the fit explains " + fmt("%.0f%%", 100.0 * e.explained) + " of the difference" +
             (e.explained < kFitExplains ? ": no mix of the terms makes your image; the difference is of another "
                                           "kind (see the conventions and the regions)"
                                         : "") +
             "\n";
    }

    s += "\nWhere (the worst regions, connected " + std::to_string(o.block) + "x" + std::to_string(o.block) +
         " blocks holding differing pixels)";
    s += in.diff_path.empty() ? ":\n" : "; error image (FLIP, magma colours): " + in.diff_path + "\n";
    int n = 0;
    for (const Region& g : e.regions) {
        s += "  " + std::to_string(++n) + ". pixels " + std::to_string(g.x0) + ".." + std::to_string(g.x1 - 1) + " x " +
             std::to_string(g.y0) + ".." + std::to_string(g.y1 - 1) + ": " + std::to_string(g.pixels) +
             " differing pixels, mean error " + fmt("%.3f", g.mean_error) + "\n";
        s += "     centre pixel " + std::to_string(g.x) + "," + std::to_string(g.y) + ": " +
             object_words(g.inspection, in.base_dir) + "; yours " + vec(g.image) + ", reference " + vec(g.reference) +
             "\n";
        s += "     reference's parts: " + parts_words(g.inspection) + "\n";
        s += "     " + lights_words(g.inspection) + " (whitted " + in.scene_path + " --inspect " + std::to_string(g.x) +
             "," + std::to_string(g.y) + " for all of it)\n";
        s += "     here: " + region_fit_words(g) + "\n";
    }
    if (e.cancelled) s += "interrupted: the explanation is incomplete\n";
    return s + verdict_name(r.verdict) + "\n";
}

std::string explain_json(const ExplainInputs& in, const ExplainOptions& o, const Explanation& e) {
    std::string compare = report_json(CompareInputs{"(whitted's render of " + in.scene_path + ")", "",
                                                    in.image_path, in.image_format, in.diff_path},
                                      o.compare, e.compare);
    while (!compare.empty() && compare.back() == '\n') compare.pop_back();
    std::string s = "{\"scene\": " + json_string(in.scene_path) + ", \"image\": " + json_string(in.image_path);
    if (!in.diff_path.empty()) s += ", \"error_image\": " + json_string(in.diff_path);
    s += ", \"result\": \"" + std::string(verdict_name(e.compare.verdict)) +
         "\", \"exit_code\": " + std::to_string(int(e.compare.verdict));
    s += ", \"differing_pixels\": " + std::to_string(e.differing) + ", \"psnr\": " + jnum(e.psnr);
    auto variant = [&](const VariantMatch& m) {
        return "{\"name\": " + json_string(m.variant.name) + ", \"words\": " + json_string(m.variant.words) +
               ", \"removal\": " + (m.variant.removal ? "true" : "false") + ", \"psnr\": " + jnum(m.psnr) +
               ", \"changes_scene\": " + (m.changes_scene ? "true" : "false") + "}";
    };
    auto list = [](const auto& items, const auto& each) {
        std::string l = "[";
        for (const auto& item : items) l += (l.size() > 1 ? ", " : "") + each(item);
        return l + "]";
    };
    s += ", \"matches\": " + list(e.matches, variant);
    s += ", \"variants\": " + list(e.variants, variant);
    auto term_json = [](const TermFit& t) {
        return "{\"name\": " + json_string(t.variant.name) + ", \"term\": " + json_string(t.variant.term) +
               ", \"coefficient\": " + jnum(t.coefficient) + ", \"share\": " + jnum(t.share) +
               ", \"words\": " + json_string(term_words(t)) + "}";
    };
    s += ", \"terms\": " + list(e.terms, term_json);
    s += ", \"explained\": " + jnum(e.explained);
    s += ", \"regions\": " + list(e.regions, [&](const Region& g) {
             const PixelReport& r = g.inspection;
             std::string j = "{\"x0\": " + std::to_string(g.x0) + ", \"y0\": " + std::to_string(g.y0) +
                             ", \"x1\": " + std::to_string(g.x1) + ", \"y1\": " + std::to_string(g.y1) +
                             ", \"pixels\": " + std::to_string(g.pixels) + ", \"mean_error\": " + jnum(g.mean_error) +
                             ", \"x\": " + std::to_string(g.x) + ", \"y\": " + std::to_string(g.y) +
                             ", \"image\": " + jvec(g.image) + ", \"reference\": " + jvec(g.reference) +
                             ", \"explained\": " + jnum(g.explained) + ", \"terms\": " + list(g.terms, term_json) +
                             ", \"words\": " + json_string(region_fit_words(g));
             j += ", \"object\": " + json_string(object_words(r, in.base_dir));
             if (r.decomposed) {
                 const ColourParts& p = r.parts;
                 j += ", \"parts\": {\"ambient\": " + jvec(p.ambient) + ", \"diffuse\": " + jvec(p.diffuse) +
                      ", \"specular\": " + jvec(p.specular) + ", \"reflect\": " + jvec(p.reflect) +
                      ", \"transparent\": " + jvec(p.transparent) + ", \"emit\": " + jvec(p.emit) +
                      ", \"background\": " + jvec(p.background) + ", \"clamped\": " + jvec(p.clamp) + "}";
             }
             j += ", \"lights\": " + json_string(lights_words(r));
             return j + "}";
         });
    s += ", \"cancelled\": " + std::string(e.cancelled ? "true" : "false");
    s += ", \"compare\": " + compare;
    return s + "}\n";
}

}  // namespace whitted
