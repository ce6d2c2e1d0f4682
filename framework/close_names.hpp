#pragma once
// Close names for an unknown one ("did you mean ...?"): every front end's message for an unknown
// algorithm or problem adds them, so a typo names its fix. One function for every list of names.
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pride {

/// The optimal string alignment distance between `a` and `b`, letters compared without case:
/// insertions, deletions, substitutions and swaps of two neighbours each cost one.
inline std::size_t name_distance(std::string_view a, std::string_view b) {
    const auto same = [](char x, char y) {
        return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
    };
    const std::size_t n = a.size(), m = b.size();
    std::vector<std::size_t> d((n + 1) * (m + 1));
    const auto at = [&](std::size_t i, std::size_t j) -> std::size_t& { return d[i * (m + 1) + j]; };
    for (std::size_t i = 0; i <= n; ++i) at(i, 0) = i;
    for (std::size_t j = 0; j <= m; ++j) at(0, j) = j;
    for (std::size_t i = 1; i <= n; ++i)
        for (std::size_t j = 1; j <= m; ++j) {
            at(i, j) =
                std::min({at(i - 1, j) + 1, at(i, j - 1) + 1, at(i - 1, j - 1) + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
            if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
                at(i, j) = std::min(at(i, j), at(i - 2, j - 2) + 1);
        }
    return at(n, m);
}

/// The names of `known` close to `name`: at most `most`, nearest first (ties in `known`'s order),
/// within one edit per three characters of `name` (at least one). A name longer than 100
/// characters has none (no typo of a registered name; the distance's table stays small).
inline std::vector<std::string> close_names(std::string_view name, const std::vector<std::string>& known,
                                            std::size_t most = 3) {
    if (name.empty() || name.size() > 100) return {};
    const std::size_t limit = std::max<std::size_t>(1, name.size() / 3);
    std::vector<std::pair<std::size_t, std::size_t>> found;  // (distance, index in known)
    for (std::size_t i = 0; i < known.size(); ++i) {
        const std::size_t length = known[i].size();
        if ((length > name.size() ? length - name.size() : name.size() - length) > limit) continue;
        if (const std::size_t d = name_distance(name, known[i]); d <= limit && known[i] != name)
            found.emplace_back(d, i);
    }
    std::stable_sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<std::string> out;
    for (std::size_t k = 0; k < found.size() && k < most; ++k) out.push_back(known[found[k].second]);
    return out;
}

/// "; did you mean 'a'?", "; did you mean 'a', 'b' or 'c'?", or "" when no name is close: what a
/// message "unknown algorithm 'x'" continues with.
inline std::string did_you_mean(std::string_view name, const std::vector<std::string>& known) {
    const auto close = close_names(name, known);
    if (close.empty()) return {};
    std::string text = "; did you mean ";
    for (std::size_t i = 0; i < close.size(); ++i)
        text += (i == 0 ? "" : i + 1 == close.size() ? " or " : ", ") + ("'" + close[i] + "'");
    return text + "?";
}

}  // namespace pride
