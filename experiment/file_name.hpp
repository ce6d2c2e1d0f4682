#pragma once
// An id as a file name, as every figure, export and page names files after problems and
// algorithms (scripts/plot_campaign.py's safe() is the same rule): anything but ASCII letters,
// digits, '-' and '.' becomes '_' (byte by byte), and a leading '.' too (no "..", no hidden file).
// Campaigns refuse two ids with one file name (experiment/campaign.cpp), case ignored.
#include <cctype>
#include <string>

namespace pride::engine {

inline std::string file_name(const std::string& id) {
    std::string s = id.empty() ? std::string("_") : id;
    for (char& c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (!(u < 128 && std::isalnum(u)) && c != '-' && c != '.') c = '_';
    }
    if (s.front() == '.') s.front() = '_';
    return s;
}

}  // namespace pride::engine
