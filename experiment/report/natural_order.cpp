#include "experiment/report/natural_order.hpp"

#include <cstddef>

namespace pride::report {
namespace {

bool digit(char c) {
    return c >= '0' && c <= '9';
}

}  // namespace

int natural_compare(std::string_view a, std::string_view b) {
    // The first difference in the number of leading zeros decides between pieces otherwise equal.
    int zeros = 0;
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (digit(a[i]) && digit(b[j])) {
            std::size_t za = i, zb = j;
            while (za < a.size() && a[za] == '0') ++za;
            while (zb < b.size() && b[zb] == '0') ++zb;
            std::size_t ea = za, eb = zb;
            while (ea < a.size() && digit(a[ea])) ++ea;
            while (eb < b.size() && digit(b[eb])) ++eb;
            // Without leading zeros, the longer run is the larger number; at equal lengths the digits decide.
            if (ea - za != eb - zb) return ea - za < eb - zb ? -1 : 1;
            if (const int c = a.substr(za, ea - za).compare(b.substr(zb, eb - zb)); c != 0) return c < 0 ? -1 : 1;
            if (zeros == 0 && ea - i != eb - j) zeros = ea - i < eb - j ? -1 : 1;
            i = ea;
            j = eb;
            continue;
        }
        if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]) ? -1 : 1;
        ++i;
        ++j;
    }
    if (i < a.size() || j < b.size()) return i < a.size() ? 1 : -1;
    return zeros;
}

}  // namespace pride::report
