#pragma once
// An InputError's place in a front end's words: the library names what was wrong in its own terms
// (`where()`: "evaluations", "parameter pop", "start x"), and each front end renames the first word
// (the command line to "--evals", "--param pop"; Python to the keyword "evals"), keeping the rest.
#include <map>
#include <optional>
#include <string>

#include "framework/error.hpp"

namespace pride {

/// "NAME REST: DETAIL", NAME being what `names` gives for the first word of e.where(); nothing when
/// the error has no place or its first word is not in `names`.
inline std::optional<std::string> renamed_message(const InputError& e,
                                                  const std::map<std::string, std::string, std::less<>>& names) {
    const std::string& where = e.where();
    if (where.empty()) return std::nullopt;
    const auto space = where.find(' ');
    const auto it = names.find(std::string_view(where).substr(0, space));
    if (it == names.end()) return std::nullopt;
    return it->second + (space == std::string::npos ? "" : where.substr(space)) + ": " + e.detail();
}

}  // namespace pride
