#pragma once
// Errors and warnings as values: FILE:LINE:COL: severity: message.
#include <string>
#include <vector>

namespace whitted {

struct SourceLoc {
    std::string file;  // path as given by the user
    int line = 0;      // 1-based; 0 = no position (whole file)
    int col = 0;       // 1-based
};

enum class Severity { Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    SourceLoc loc;
    std::string message;

    // "file:line:col: error: message" (the form every frontend prints).
    std::string str() const;
};

bool has_errors(const std::vector<Diagnostic>& diags);

}  // namespace whitted
