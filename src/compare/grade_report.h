#pragma once
// `whitted grade`'s report of a class: a table of scenes × submissions (each cell the metrics of
// `whitted compare`, its verdict and explain's one-line account, or why there is nothing to
// compare) told as one static HTML page, as CSV and as JSON. The page links image files beside it
// (relative paths) and needs no script, no server and no network.
#include <string>
#include <vector>

#include "compare/errors.h"

namespace whitted {

// not_theirs: a row of another student's own scene (nothing asked of this student: not counted).
enum class CellStatus { compared, missing, wrong_size, unreadable, scene_error, timed_out, not_theirs };

struct GradeCell {
    std::string scene, student;
    CellStatus status = CellStatus::missing;
    std::string problem;  // for any status but compared: what is wrong, in words
    Verdict verdict = Verdict::fail;  // compared: the compare thresholds' verdict
    double psnr = 0.0, flip_mean = 0.0, ssim_worst = 1.0;
    std::string explanation;  // explain's one line, or "" when not explained
    // The student's own scene file the reference was rendered from ("" = the class's scene).
    std::string scene_file;
    // Files in the report's folder (relative names), or "".
    std::string image_file, reference_file, error_file;
};

struct GradeReport {
    std::vector<std::string> scenes, students;  // rows and columns, in order
    std::vector<GradeCell> cells;               // row-major: scenes × students
};

// "pass", "warn", "fail" for a compared cell; "missing", "wrong size", "unreadable", "scene error",
// "time limit"; "" for a row that is not the student's.
std::string cell_result(const GradeCell& c);

// 0 when every cell passes, 1 when the worst is a warning, 2 when any cell fails or has nothing to
// compare (missing, wrong size, unreadable, a scene that would not load or ran out of time). Rows
// of another student's own scene do not count.
int grade_exit_code(const GradeReport& r);

// `s` with & < > " ' as HTML entities.
std::string html_escape(const std::string& s);

std::string grade_html(const GradeReport& r);
// One header line, then one line per cell (RFC 4180 quoting).
std::string grade_csv(const GradeReport& r);
std::string grade_json(const GradeReport& r);

}  // namespace whitted
