#pragma once
// UTF-8 decoding, written once for every reader and printer that checks text: the map and table
// readers (which refuse what is not UTF-8, naming its line and column) and the one-line error
// messages (which show valid UTF-8 as itself and escape the rest).
#include <cstddef>
#include <string_view>

namespace pride {

/// The length (1 to 4) of the valid UTF-8 sequence at s[i], or 0 when the bytes there are not
/// UTF-8: overlong forms, surrogates, code points above U+10FFFF and truncated sequences are
/// refused. With `cp`, the code point is stored there.
constexpr std::size_t utf8_length(std::string_view s, std::size_t i, char32_t* cp = nullptr) noexcept {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
    const unsigned char c = b(0);
    const std::size_t n = s.size() - i;
    const auto cont = [&](std::size_t k) { return k < n && (b(k) & 0xC0) == 0x80; };
    char32_t v = 0;
    std::size_t len = 0;
    if (c < 0x80) {
        v = c;
        len = 1;
    } else if (c >= 0xC2 && c <= 0xDF) {
        if (!cont(1)) return 0;
        v = (char32_t{c} & 0x1F) << 6 | (b(1) & 0x3F);
        len = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
        if (!cont(1) || !cont(2)) return 0;
        v = (char32_t{c} & 0x0F) << 12 | char32_t(b(1) & 0x3F) << 6 | (b(2) & 0x3F);
        if (v < 0x800 || (v >= 0xD800 && v <= 0xDFFF)) return 0;
        len = 3;
    } else if (c >= 0xF0 && c <= 0xF4) {
        if (!cont(1) || !cont(2) || !cont(3)) return 0;
        v = (char32_t{c} & 0x07) << 18 | char32_t(b(1) & 0x3F) << 12 | char32_t(b(2) & 0x3F) << 6 | (b(3) & 0x3F);
        if (v < 0x10000 || v > 0x10FFFF) return 0;
        len = 4;
    } else {
        return 0;
    }
    if (cp) *cp = v;
    return len;
}

}  // namespace pride
