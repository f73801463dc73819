#pragma once
// Shared helpers for the parser tests: parse a string, check where the (single) error is.
#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "parse/parser.h"

namespace whitted::parse_test {

// A minimal valid scene body, appended to snippets that test something else.
inline constexpr const char* kRoot = "mastersubgraph root [ trans [ object cube [ ] ] ]\n";

inline ParseResult parse(std::string_view text, bool lenient = false) {
    ParseOptions options;
    options.lenient = lenient;
    return parse_scene_text(text, "t.sc", options);
}

inline const Diagnostic* first_error(const ParseResult& r) {
    for (const auto& d : r.diagnostics)
        if (d.severity == Severity::Error) return &d;
    return nullptr;
}

inline int count(const ParseResult& r, Severity s) {
    int n = 0;
    for (const auto& d : r.diagnostics) n += d.severity == s;
    return n;
}

// The parse failed with its first error at line:col, in file "t.sc", mentioning `text`.
inline ::testing::AssertionResult error_at(const ParseResult& r, int line, int col,
                                           std::string_view text) {
    const Diagnostic* e = first_error(r);
    if (!e) return ::testing::AssertionFailure() << "no error";
    if (e->loc.file != "t.sc" || e->loc.line != line || e->loc.col != col ||
        e->message.find(text) == std::string::npos)
        return ::testing::AssertionFailure() << "got \"" << e->str() << "\", expected t.sc:" << line
                                             << ":" << col << " with \"" << text << "\"";
    return ::testing::AssertionSuccess();
}

// The parse succeeded; on failure, show the diagnostics.
inline ::testing::AssertionResult parsed_ok(const ParseResult& r) {
    if (r.ok()) return ::testing::AssertionSuccess();
    auto failure = ::testing::AssertionFailure();
    for (const auto& d : r.diagnostics) failure << d.str() << "\n";
    return failure;
}

}  // namespace whitted::parse_test
