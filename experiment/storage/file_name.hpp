#pragma once
// An id as a file name, as every figure, export and page names files after problems and
// algorithms (scripts/plot_campaign.py's safe() is the same rule): anything but ASCII letters,
// digits, '-' and '.' becomes '_' (byte by byte), and a leading '.' too (no "..", no hidden file).
// Campaigns refuse two ids with one file name (experiment/campaign.cpp), case ignored.
#include <fmt/format.h>

#include <cctype>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace pride::storage {

inline std::string file_name(const std::string& id) {
    std::string s = id.empty() ? std::string("_") : id;
    for (char& c : s) {
        const auto u = static_cast<unsigned char>(c);
        if (!(u < 128 && std::isalnum(u)) && c != '-' && c != '.') c = '_';
    }
    if (s.front() == '.') s.front() = '_';
    return s;
}

/// For ids from anywhere (stores merged or written before campaigns refused clashes):
/// one file name per id, each a safe file name, no two alike: an id that is a safe
/// name already keeps it; one that had to change gets a hash of the id (FNV-1a) after it, so
/// that "a/b" and "a_b" never share a folder; a clash left over (or the same name in another
/// case, for case-insensitive file systems) is numbered.
inline std::map<std::string, std::string> unique_file_names(const std::vector<std::string>& ids) {
    const auto lower = [](std::string s) {
        for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return s;
    };
    std::map<std::string, std::string> out;
    std::set<std::string> used;  // lower case
    std::vector<std::string> changed;
    for (const auto& id : ids)
        if (file_name(id) == id && used.insert(lower(id)).second)
            out[id] = id;
        else
            changed.push_back(id);
    for (const auto& id : changed) {
        std::uint64_t h = 1469598103934665603ull;
        for (const unsigned char c : id) h = (h ^ c) * 1099511628211ull;
        std::string name = fmt::format("{}-{:08x}", file_name(id), static_cast<std::uint32_t>(h ^ (h >> 32)));
        for (int k = 2; !used.insert(lower(name)).second; ++k)
            name = fmt::format("{}-{:08x}-{}", file_name(id), static_cast<std::uint32_t>(h ^ (h >> 32)), k);
        out[id] = name;
    }
    return out;
}

}  // namespace pride::storage
