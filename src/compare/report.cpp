#include "compare/report.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace whitted {
namespace {

const char* const kChannel[3] = {"R", "G", "B"};

std::string fmt(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

// A JSON number: shortest form that reads back to the same double; null if not finite.
std::string num(double v) {
    if (!std::isfinite(v)) return "null";
    for (int precision = 6; precision < 17; ++precision) {
        const std::string s = fmt(("%." + std::to_string(precision) + "g").c_str(), v);
        if (std::strtod(s.c_str(), nullptr) == v) return s;
    }
    return fmt("%.17g", v);
}

// The same for a float (a threshold as given): the shortest form that reads back to it.
std::string num(float v) {
    if (!std::isfinite(v)) return "null";
    for (int precision = 6; precision < 9; ++precision) {
        const std::string s = fmt(("%." + std::to_string(precision) + "g").c_str(), v);
        if (std::strtof(s.c_str(), nullptr) == v) return s;
    }
    return fmt("%.9g", v);
}

std::string percent(std::size_t part, std::size_t whole) {
    return fmt("%.2f%%", whole ? 100.0 * double(part) / double(whole) : 0.0);
}

std::string pixel(int x, int y) { return std::to_string(x) + "," + std::to_string(y); }

// Length in UTF-8 characters of a valid sequence starting at s[i], or 0 if s[i] starts none.
std::size_t utf8_length(const std::string& s, std::size_t i) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (n == 0 || i + n > s.size()) return 0;
    for (std::size_t k = 1; k < n; ++k)
        if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
    return n;
}

}  // namespace

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (std::size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        if (c == '"' || c == '\\') {
            out += '\\', out += char(c), ++i;
        } else if (c < 0x20) {
            out += fmt("\\u%04x", c), ++i;
        } else if (const std::size_t n = utf8_length(s, i); n > 0) {
            out.append(s, i, n), i += n;
        } else {
            out += "\\ufffd", ++i;
        }
    }
    return out + "\"";
}

std::string report_text(const CompareInputs& in, const CompareOptions& o, const CompareReport& r) {
    const ErrorStats& e = r.errors;
    const Thresholds& t = o.thresholds;
    auto line = [](const std::string& label, const std::string& text) {
        std::string l = "  " + label;
        l.resize(16, ' ');
        return l + text + "\n";
    };
    std::string s = "Comparing \"" + in.path_a + "\" (" + in.format_a + ") and \"" + in.path_b + "\" (" + in.format_b +
                    "), " + std::to_string(r.width) + "x" + std::to_string(r.height) + "\n";
    s += line("PSNR", std::isfinite(e.psnr) ? fmt("%.2f dB", e.psnr) : "infinite (the images are equal)");
    s += line("mean error", fmt("%.6f", e.mean_error) + " per channel (RMS " + fmt("%.6f", e.rms_error) + ")");
    if (e.max_error > 0.0)
        s += line("max error", fmt("%.6f", e.max_error) + " at pixel " + pixel(e.max_x, e.max_y) + " (" +
                                   kChannel[e.max_channel] + "): " + fmt("%.6g", e.max_a) + " in A, " +
                                   fmt("%.6g", e.max_b) + " in B");
    else
        s += line("max error", "0");
    auto threshold = [&](const char* verdict, std::size_t n, float over, float allowed, float hard) {
        std::string text = std::to_string(n) + " pixels (" + percent(n, e.pixels) + ") by more than " + fmt("%g", over) +
                           "; " + verdict + " above " + fmt("%g", allowed) + "% of the pixels";
        if (std::isfinite(hard)) text += " or any difference above " + fmt("%g", hard);
        return text;
    };
    s += line("over --warn", threshold("WARNING", e.warn_pixels, t.warn, t.warn_percent, t.hard_warn));
    s += line("over --fail", threshold("FAILURE", e.fail_pixels, t.fail, t.fail_percent, t.hard_fail));
    const SsimStats& q = r.ssim;
    s += line("SSIM " + std::to_string(o.ssim.block) + "x" + std::to_string(o.ssim.block),
              "mean " + fmt("%.4f", q.mean) + ", worst " + fmt("%.4f", q.worst.ssim) + " in the block at " +
                  pixel(q.worst.x, q.worst.y) + "; " + std::to_string(q.blocks_failing) + " of " +
                  std::to_string(q.blocks) + " blocks (" + percent(q.blocks_failing, q.blocks) + ") at or below " +
                  fmt("%g", o.ssim.threshold));
    s += line("FLIP", "mean " + fmt("%.4f", r.flip.mean) + ", max " + fmt("%.4f", r.flip.max) +
                          (r.flip.max > 0.0 ? " at pixel " + pixel(r.flip.max_x, r.flip.max_y) : "") + " (" +
                          fmt("%.1f", o.flip.pixels_per_degree) + " pixels per degree)");
    return s + verdict_name(r.verdict) + "\n";
}

std::string report_json(const CompareInputs& in, const CompareOptions& o, const CompareReport& r) {
    const ErrorStats& e = r.errors;
    const Thresholds& t = o.thresholds;
    const SsimStats& q = r.ssim;
    auto image = [](const std::string& path, const std::string& format) {
        return "{\"path\": " + json_string(path) + ", \"format\": " + json_string(format) + "}";
    };
    auto threshold = [&](float over, float allowed, float hard, std::size_t n) {
        return "{\"threshold\": " + num(over) + ", \"percent\": " + num(allowed) + ", \"hard\": " + num(hard) +
               ", \"pixels\": " + std::to_string(n) + ", \"share\": " + num(e.pixels ? double(n) / double(e.pixels) : 0.0) +
               "}";
    };
    std::string max = "{\"value\": " + num(e.max_error);
    if (e.max_error > 0.0)
        max += ", \"x\": " + std::to_string(e.max_x) + ", \"y\": " + std::to_string(e.max_y) + ", \"channel\": \"" +
               kChannel[e.max_channel] + "\", \"a\": " + num(e.max_a) + ", \"b\": " + num(e.max_b);
    max += "}";
    std::string s = "{";
    s += "\"a\": " + image(in.path_a, in.format_a) + ", \"b\": " + image(in.path_b, in.format_b);
    if (!in.diff_path.empty()) s += ", \"diff_image\": " + json_string(in.diff_path);
    s += ", \"width\": " + std::to_string(r.width) + ", \"height\": " + std::to_string(r.height);
    s += ", \"result\": \"" + std::string(verdict_name(r.verdict)) + "\", \"exit_code\": " + std::to_string(int(r.verdict));
    s += ", \"psnr\": " + num(e.psnr) + ", \"peak\": " + num(e.peak);
    s += ", \"mean_error\": " + num(e.mean_error) + ", \"rms_error\": " + num(e.rms_error);
    s += ", \"max_error\": " + max;
    s += ", \"warn\": " + threshold(t.warn, t.warn_percent, t.hard_warn, e.warn_pixels);
    s += ", \"fail\": " + threshold(t.fail, t.fail_percent, t.hard_fail, e.fail_pixels);
    s += ", \"ssim\": {\"block\": " + std::to_string(o.ssim.block) + ", \"threshold\": " + num(o.ssim.threshold) +
         ", \"mean\": " + num(q.mean) + ", \"worst\": {\"ssim\": " + num(q.worst.ssim) + ", \"x\": " +
         std::to_string(q.worst.x) + ", \"y\": " + std::to_string(q.worst.y) + ", \"width\": " +
         std::to_string(q.worst.width) + ", \"height\": " + std::to_string(q.worst.height) + "}, \"blocks\": " +
         std::to_string(q.blocks) + ", \"blocks_failing\": " + std::to_string(q.blocks_failing) +
         ", \"share_failing\": " + num(q.blocks ? double(q.blocks_failing) / double(q.blocks) : 0.0) + "}";
    s += ", \"flip\": {\"mean\": " + num(r.flip.mean) + ", \"max\": " + num(r.flip.max) + ", \"x\": " +
         std::to_string(r.flip.max_x) + ", \"y\": " + std::to_string(r.flip.max_y) +
         ", \"pixels_per_degree\": " + num(o.flip.pixels_per_degree) + "}";
    return s + "}\n";
}

}  // namespace whitted
