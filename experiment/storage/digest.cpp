#include "experiment/storage/digest.hpp"

#include <fmt/format.h>

namespace pride::storage {
namespace {

/// The part of a digest after "LABEL sha256:", or empty.
std::string digest_part(const std::string& digest, const std::string& label) {
    const std::string key = label + " sha256:";
    const auto at = digest.find(key);
    return at == std::string::npos ? std::string() : digest.substr(at + key.size(), 64);
}

}  // namespace

std::string digest_difference(const std::string& stored, const std::string& now) {
    const auto shown = [](const std::string& hex) { return hex.empty() ? std::string("none") : hex.substr(0, 16); };
    for (const char* part : {"map", "settings"}) {
        const std::string a = digest_part(stored, part), b = digest_part(now, part);
        if (a != b)
            return fmt::format("has {} than the stored one{} ({}; sha256 {}... stored, {}... now)",
                               part == std::string("map") ? "another map" : "other settings",
                               part == std::string("map") ? "" : "s",
                               part == std::string("map") ? "its cells or size differ: the map was edited, or another "
                                                            "map given"
                                                          : "its start, goal, objective, weights, bounds or another "
                                                            "setting differ",
                               shown(a), shown(b));
    }
    return "differs from the stored one (" + stored + " stored, " + now + " now)";
}

}  // namespace pride::storage
