#include "compare/grade_report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "compare/report.h"

namespace whitted {
namespace {

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

std::string psnr_text(double psnr) { return std::isinf(psnr) ? std::string("inf") : fmt("%.2f", psnr); }

std::string jnum(double v) { return std::isfinite(v) ? fmt("%.6g", v) : std::string("null"); }

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

// A relative file name as a URL path: percent-encoded bytes outside the unreserved set, so a
// name with '#', '?', '%' or a space still finds its file from a file:// page.
std::string url_path(const std::string& s) {
    std::string out;
    for (unsigned char c : s) {
        if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~' || c == '/')
            out += char(c);
        else
            out += fmt("%%%02X", c);
    }
    return out;
}

const char* css_class(const GradeCell& c) {
    if (c.status == CellStatus::not_theirs) return "none";
    if (c.status != CellStatus::compared) return "bad";
    return c.verdict == Verdict::pass ? "pass" : c.verdict == Verdict::warn ? "warn" : "fail";
}

std::string img(const std::string& file, const char* title) {
    if (file.empty()) return "";
    return "<a href=\"" + html_escape(url_path(file)) + "\"><img src=\"" + html_escape(url_path(file)) +
           "\" alt=\"" + title + "\" title=\"" + title + "\"></a>";
}

}  // namespace

std::string cell_result(const GradeCell& c) {
    switch (c.status) {
        case CellStatus::compared: return c.verdict == Verdict::pass ? "pass" : c.verdict == Verdict::warn ? "warn" : "fail";
        case CellStatus::missing: return "missing";
        case CellStatus::wrong_size: return "wrong size";
        case CellStatus::unreadable: return "unreadable";
        case CellStatus::scene_error: return "scene error";
        case CellStatus::timed_out: return "time limit";
        case CellStatus::not_theirs: return "";
    }
    return "fail";
}

int grade_exit_code(const GradeReport& r) {
    int code = 0;
    for (const GradeCell& c : r.cells)
        if (c.status != CellStatus::not_theirs)
            code = std::max(code, c.status == CellStatus::compared ? int(c.verdict) : 2);
    return code;
}

std::string html_escape(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string grade_html(const GradeReport& r) {
    std::string s =
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>whitted grade</title>\n"
        "<style>\n"
        "body{font-family:sans-serif;margin:16px;background:#fff;color:#111}\n"
        "table{border-collapse:collapse}\n"
        "th,td{border:1px solid #999;padding:6px;vertical-align:top;text-align:left}\n"
        "td img{width:96px;image-rendering:pixelated;margin-right:4px}\n"
        ".pass{background:#e3f6e3}.warn{background:#fff4d6}.fail{background:#fde0e0}.bad{background:#e6e6e6}\n"
        ".result{font-weight:bold}.words{max-width:22em;font-size:90%}\n"
        "</style>\n</head>\n<body>\n<h1>whitted grade</h1>\n"
        "<p>Each cell: the submitted image, whitted's reference at its size and the FLIP error image; PSNR (dB), "
        "mean FLIP (0 = identical), the worst 8&times;8 SSIM block, the verdict of the compare thresholds and, "
        "where explained, the mistake the image looks like.</p>\n"
        "<table>\n<tr><th>scene</th>";
    for (const std::string& student : r.students) s += "<th>" + html_escape(student) + "</th>";
    s += "</tr>\n";
    for (std::size_t i = 0; i < r.scenes.size(); ++i) {
        s += "<tr><th>" + html_escape(r.scenes[i]) + "</th>";
        for (std::size_t j = 0; j < r.students.size(); ++j) {
            const GradeCell& c = r.cells[i * r.students.size() + j];
            s += "<td class=\"" + std::string(css_class(c)) + "\">";
            s += img(c.image_file, "submitted") + img(c.reference_file, "reference") + img(c.error_file, "error");
            if (c.status == CellStatus::not_theirs) {
                s += "</td>";
                continue;
            }
            s += "<div class=\"result\">" + html_escape(cell_result(c)) + "</div>";
            if (!c.scene_file.empty())
                s += "<div class=\"words\">rendered from the student's " + html_escape(c.scene_file) + "</div>";
            if (c.status == CellStatus::compared)
                s += "<div>PSNR " + psnr_text(c.psnr) + " &middot; FLIP " + fmt("%.4f", c.flip_mean) +
                     " &middot; SSIM min " + fmt("%.4f", c.ssim_worst) + "</div>";
            else
                s += "<div class=\"words\">" + html_escape(c.problem) + "</div>";
            if (!c.explanation.empty()) s += "<div class=\"words\">" + html_escape(c.explanation) + "</div>";
            s += "</td>";
        }
        s += "</tr>\n";
    }
    return s + "</table>\n</body>\n</html>\n";
}

std::string grade_csv(const GradeReport& r) {
    std::string s = "scene,student,result,psnr,flip_mean,ssim_worst,explanation,problem,scene_file\n";
    for (const GradeCell& c : r.cells) {
        if (c.status == CellStatus::not_theirs) continue;
        const bool m = c.status == CellStatus::compared;
        s += csv_field(c.scene) + "," + csv_field(c.student) + "," + csv_field(cell_result(c)) + "," +
             (m ? psnr_text(c.psnr) : "") + "," + (m ? fmt("%.6g", c.flip_mean) : "") + "," +
             (m ? fmt("%.6g", c.ssim_worst) : "") + "," + csv_field(c.explanation) + "," + csv_field(c.problem) + "," +
             csv_field(c.scene_file) + "\n";
    }
    return s;
}

std::string grade_json(const GradeReport& r) {
    std::string s = "{\"exit_code\":" + std::to_string(grade_exit_code(r)) + ",\"scenes\":[";
    for (std::size_t i = 0; i < r.scenes.size(); ++i) {
        if (i) s += ",";
        s += json_string(r.scenes[i]);
    }
    s += "],\"students\":[";
    for (std::size_t i = 0; i < r.students.size(); ++i) {
        if (i) s += ",";
        s += json_string(r.students[i]);
    }
    s += "],\"cells\":[";
    bool first = true;
    for (const GradeCell& c : r.cells) {
        if (c.status == CellStatus::not_theirs) continue;
        const bool m = c.status == CellStatus::compared;
        s += std::string(first ? "" : ",") + "\n{\"scene\":" + json_string(c.scene) + ",\"student\":" +
             json_string(c.student) + ",\"result\":" + json_string(cell_result(c)) +
             ",\"psnr\":" + (m ? jnum(c.psnr) : "null") + ",\"flip_mean\":" + (m ? jnum(c.flip_mean) : "null") +
             ",\"ssim_worst\":" + (m ? jnum(c.ssim_worst) : "null") + ",\"explanation\":" + json_string(c.explanation) +
             ",\"problem\":" + json_string(c.problem) + ",\"image\":" + json_string(c.image_file) +
             ",\"reference\":" + json_string(c.reference_file) + ",\"error_image\":" + json_string(c.error_file) + ",\"scene_file\":" + json_string(c.scene_file) + "}";
        first = false;
    }
    return s + "\n]}\n";
}

}  // namespace whitted
