#include "base/diagnostic.h"

namespace whitted {

std::string Diagnostic::str() const {
    std::string s;
    s.reserve(loc.file.size() + message.size() + 32);
    s.append(loc.file);
    if (loc.line > 0) {
        s.append(":").append(std::to_string(loc.line));
        s.append(":").append(std::to_string(loc.col));
    }
    s.append(severity == Severity::Error ? ": error: " : ": warning: ");
    s.append(message);
    return s;
}

bool has_errors(const std::vector<Diagnostic>& diags) {
    for (const auto& d : diags)
        if (d.severity == Severity::Error) return true;
    return false;
}

}  // namespace whitted
