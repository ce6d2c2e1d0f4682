#pragma once
// A small strict JSON reader for the command-line tests (no JSON library is available): enough to
// check the documents pride prints. Object members are kept in order, duplicates included, so that
// duplicate keys can be detected. Malformed input throws std::runtime_error with a one-line message
// "JSON: <what> at offset <n>".
#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace pride::test {

struct JsonMember;

struct JsonValue {
    enum class Kind { null, boolean, number, string, array, object } kind = Kind::null;
    bool boolean = false;
    double number = 0.0;
    std::string text;  // a string's value, or a number's literal text
    std::vector<JsonValue> items;
    // Not std::pair<std::string, JsonValue>: a pair of an incomplete type is undefined, and clang
    // with libstdc++ refuses it (the sanitizer build).
    std::vector<JsonMember> members;

    bool has(const std::string& key) const;
    /// The first member named `key`; throws if there is none.
    const JsonValue& at(const std::string& key) const;
    /// Member names in document order, duplicates included.
    std::vector<std::string> keys() const;
    bool is_number() const { return kind == Kind::number; }
    /// A number written without fraction or exponent.
    bool is_integer() const { return kind == Kind::number && text.find_first_of(".eE") == std::string::npos; }
};

struct JsonMember {
    std::string first;
    JsonValue second;
};

inline bool JsonValue::has(const std::string& key) const {
    return std::any_of(members.begin(), members.end(), [&](const JsonMember& m) { return m.first == key; });
}
inline const JsonValue& JsonValue::at(const std::string& key) const {
    for (const auto& [k, v] : members)
        if (k == key) return v;
    throw std::runtime_error("JSON: no member '" + key + "'");
}
inline std::vector<std::string> JsonValue::keys() const {
    std::vector<std::string> out;
    for (const auto& m : members) out.push_back(m.first);
    return out;
}

class JsonParser {
  public:
    explicit JsonParser(const std::string& s) : s_(s) {}

    /// The whole input as one JSON value (surrounding white space allowed, nothing else).
    JsonValue parse() {
        JsonValue v = value();
        skip();
        if (i_ != s_.size()) fail("trailing characters");
        return v;
    }

  private:
    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("JSON: " + what + " at offset " + std::to_string(i_));
    }
    void skip() {
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\t' || s_[i_] == '\r')) ++i_;
    }
    bool accept(char c) {
        skip();
        if (i_ < s_.size() && s_[i_] == c) {
            ++i_;
            return true;
        }
        return false;
    }
    void expect(char c) {
        if (!accept(c)) fail(std::string("expected '") + c + "'");
    }
    bool literal(const std::string& w) {
        if (s_.compare(i_, w.size(), w) != 0) return false;
        i_ += w.size();
        return true;
    }
    /// The four hex digits of a \u escape.
    unsigned hex4() {
        if (i_ + 4 > s_.size()) fail("bad \\u escape");
        unsigned code = 0;
        for (int k = 0; k < 4; ++k) {
            const char h = s_[i_];
            unsigned d = 0;
            if (h >= '0' && h <= '9')
                d = static_cast<unsigned>(h - '0');
            else if (h >= 'a' && h <= 'f')
                d = static_cast<unsigned>(h - 'a' + 10);
            else if (h >= 'A' && h <= 'F')
                d = static_cast<unsigned>(h - 'A' + 10);
            else
                fail("bad \\u escape");
            code = code * 16 + d;
            ++i_;
        }
        return code;
    }
    static void append_utf8(std::string& out, unsigned cp) {
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xC0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += static_cast<char>(0xE0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (cp >> 18));
            out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }
    std::string string_value() {
        expect('"');
        std::string out;
        for (;;) {
            if (i_ >= s_.size()) fail("unterminated string");
            const char c = s_[i_++];
            if (c == '"') return out;
            if (static_cast<unsigned char>(c) < 0x20) fail("control character in a string");
            if (c != '\\') {
                out += c;
                continue;
            }
            if (i_ >= s_.size()) fail("bad escape");
            const char e = s_[i_++];
            switch (e) {
                case '"':
                case '\\':
                case '/':
                    out += e;
                    break;
                case 'b':
                    out += '\b';
                    break;
                case 'f':
                    out += '\f';
                    break;
                case 'n':
                    out += '\n';
                    break;
                case 'r':
                    out += '\r';
                    break;
                case 't':
                    out += '\t';
                    break;
                case 'u': {
                    unsigned cp = hex4();
                    if (cp >= 0xDC00 && cp <= 0xDFFF) fail("unpaired surrogate in \\u escape");
                    if (cp >= 0xD800 && cp <= 0xDBFF) {
                        if (!literal("\\u")) fail("unpaired surrogate in \\u escape");
                        const unsigned low = hex4();
                        if (low < 0xDC00 || low > 0xDFFF) fail("unpaired surrogate in \\u escape");
                        cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                    }
                    append_utf8(out, cp);
                    break;
                }
                default:
                    fail("bad escape");
            }
        }
    }
    JsonValue value() {
        skip();
        if (i_ >= s_.size()) fail("unexpected end");
        JsonValue v;
        const char c = s_[i_];
        if (c == '{') {
            ++i_;
            v.kind = JsonValue::Kind::object;
            if (accept('}')) return v;
            do {
                skip();
                std::string key = string_value();
                expect(':');
                v.members.push_back(JsonMember{std::move(key), value()});
            } while (accept(','));
            expect('}');
        } else if (c == '[') {
            ++i_;
            v.kind = JsonValue::Kind::array;
            if (accept(']')) return v;
            do v.items.push_back(value());
            while (accept(','));
            expect(']');
        } else if (c == '"') {
            v.kind = JsonValue::Kind::string;
            v.text = string_value();
        } else if (literal("true")) {
            v.kind = JsonValue::Kind::boolean;
            v.boolean = true;
        } else if (literal("false")) {
            v.kind = JsonValue::Kind::boolean;
        } else if (literal("null")) {
            v.kind = JsonValue::Kind::null;
        } else {
            // number: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
            const std::size_t start = i_;
            const auto digits = [&] {
                const std::size_t d = i_;
                while (i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9') ++i_;
                return i_ - d;
            };
            if (i_ < s_.size() && s_[i_] == '-') ++i_;
            if (i_ < s_.size() && s_[i_] == '0')
                ++i_;
            else if (digits() == 0)
                fail("bad value");
            if (i_ < s_.size() && s_[i_] == '.') {
                ++i_;
                if (digits() == 0) fail("bad fraction");
            }
            if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
                ++i_;
                if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
                if (digits() == 0) fail("bad exponent");
            }
            v.kind = JsonValue::Kind::number;
            v.text = s_.substr(start, i_ - start);
            v.number = std::strtod(v.text.c_str(), nullptr);
        }
        return v;
    }

    const std::string& s_;
    std::size_t i_ = 0;
};

/// Parses a whole JSON document; throws std::runtime_error ("JSON: ... at offset n") if malformed.
inline JsonValue parse_json(const std::string& s) {
    return JsonParser(s).parse();
}

}  // namespace pride::test
