#pragma once
// `whitted grade SCENES_DIR SUBMISSIONS_DIR -o REPORT_DIR`: every student's images against
// whitted's renders of the reference scenes, as one HTML page, a CSV and a JSON file
// (src/compare/grade_report.h).

namespace whitted::cli {

// Exit codes: 0 every cell passes, 1 the worst is a warning, 2 some cell fails (or is missing,
// the wrong size, unreadable, or its scene would not load); 4 the report cannot be written, 5 bad
// usage (or a folder that cannot be listed); 130 interrupted.
constexpr int kGradePass = 0, kGradeWarn = 1, kGradeFail = 2, kGradeFile = 4, kGradeUsage = 5;

// Runs the subcommand; argv[0] is "grade". Returns the exit code.
int grade_main(int argc, char** argv);

}  // namespace whitted::cli
