#pragma once
// A small strict JSON reader for tests that parse a program's --json output back (RFC 8259:
// objects, arrays, strings with escapes, numbers, true, false, null). Throws std::runtime_error
// on anything else, trailing text included, so that malformed output fails the test.
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace whitted::test {

struct Json {
    enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
    bool boolean = false;
    double number = 0.0;
    std::string string;
    std::vector<Json> array;
    std::map<std::string, Json> object;

    bool has(const std::string& key) const { return kind == Object && object.count(key) > 0; }
    const Json& operator[](const std::string& key) const {
        if (!has(key)) throw std::runtime_error("no key '" + key + "'");
        return object.at(key);
    }
    bool is_null() const { return kind == Null; }

    static Json parse(const std::string& text) {
        std::size_t i = 0;
        Json j = value(text, i);
        skip(text, i);
        if (i != text.size()) throw std::runtime_error("text after the JSON value at " + std::to_string(i));
        return j;
    }

private:
    static void skip(const std::string& t, std::size_t& i) {
        while (i < t.size() && (t[i] == ' ' || t[i] == '\n' || t[i] == '\r' || t[i] == '\t')) ++i;
    }
    static void expect(const std::string& t, std::size_t& i, const std::string& word) {
        if (t.compare(i, word.size(), word) != 0) throw std::runtime_error("expected '" + word + "' at " + std::to_string(i));
        i += word.size();
    }
    static std::string str(const std::string& t, std::size_t& i) {
        expect(t, i, "\"");
        std::string s;
        while (i < t.size() && t[i] != '"') {
            const unsigned char c = static_cast<unsigned char>(t[i++]);
            if (c < 0x20) throw std::runtime_error("a control character in a string");
            if (c != '\\') {
                s += char(c);
                continue;
            }
            if (i >= t.size()) break;
            const char e = t[i++];
            switch (e) {
                case '"': case '\\': case '/': s += e; break;
                case 'b': s += '\b'; break;
                case 'f': s += '\f'; break;
                case 'n': s += '\n'; break;
                case 'r': s += '\r'; break;
                case 't': s += '\t'; break;
                case 'u': {
                    if (i + 4 > t.size()) throw std::runtime_error("a short \\u escape");
                    const unsigned cp = unsigned(std::stoul(t.substr(i, 4), nullptr, 16));
                    i += 4;
                    if (cp < 0x80) {
                        s += char(cp);
                    } else if (cp < 0x800) {
                        s += char(0xC0 | (cp >> 6)), s += char(0x80 | (cp & 0x3F));
                    } else {
                        s += char(0xE0 | (cp >> 12)), s += char(0x80 | ((cp >> 6) & 0x3F)), s += char(0x80 | (cp & 0x3F));
                    }
                    break;
                }
                default: throw std::runtime_error("a bad escape");
            }
        }
        expect(t, i, "\"");
        return s;
    }
    static Json value(const std::string& t, std::size_t& i) {
        skip(t, i);
        if (i >= t.size()) throw std::runtime_error("the text ends where a value should be");
        Json j;
        const char c = t[i];
        if (c == '{') {
            j.kind = Object;
            ++i;
            skip(t, i);
            if (i < t.size() && t[i] == '}') return ++i, j;
            for (;;) {
                skip(t, i);
                std::string key = str(t, i);
                skip(t, i);
                expect(t, i, ":");
                if (j.object.count(key)) throw std::runtime_error("the key '" + key + "' twice");
                j.object[key] = value(t, i);
                skip(t, i);
                if (i < t.size() && t[i] == ',') { ++i; continue; }
                expect(t, i, "}");
                return j;
            }
        }
        if (c == '[') {
            j.kind = Array;
            ++i;
            skip(t, i);
            if (i < t.size() && t[i] == ']') return ++i, j;
            for (;;) {
                j.array.push_back(value(t, i));
                skip(t, i);
                if (i < t.size() && t[i] == ',') { ++i; continue; }
                expect(t, i, "]");
                return j;
            }
        }
        if (c == '"') {
            j.kind = String;
            j.string = str(t, i);
            return j;
        }
        if (t.compare(i, 4, "true") == 0) return i += 4, j.kind = Bool, j.boolean = true, j;
        if (t.compare(i, 5, "false") == 0) return i += 5, j.kind = Bool, j;
        if (t.compare(i, 4, "null") == 0) return i += 4, j;
        // A number: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
        const std::size_t start = i;
        auto digits = [&] {
            const std::size_t from = i;
            while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
            if (i == from) throw std::runtime_error("a bad number at " + std::to_string(start));
        };
        if (t[i] == '-') ++i;
        if (i < t.size() && t[i] == '0') ++i; else digits();
        if (i < t.size() && t[i] == '.') ++i, digits();
        if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
            ++i;
            if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
            digits();
        }
        j.kind = Number;
        j.number = std::strtod(t.substr(start, i - start).c_str(), nullptr);
        return j;
    }
};

}  // namespace whitted::test
