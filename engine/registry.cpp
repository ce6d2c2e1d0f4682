#include "engine/registry.hpp"

#include <algorithm>
#include <stdexcept>

#include "framework/close_names.hpp"
#include "framework/error.hpp"

namespace pride::engine {

void register_builtin_algorithms(AlgorithmRegistry& registry);  // made by CMake from engine/entries/

std::vector<std::string> AlgorithmEntry::spaces() const {
    std::vector<std::string> out;
    if (runs(Kind::box)) out.emplace_back("box");
    if (runs(Kind::chain)) out.emplace_back("chain");
    if (whole_map()) out.emplace_back("grid");
    if (runs(Kind::multiobjective)) out.emplace_back("multi-objective");
    if (runs(Kind::multiobjective_chain)) out.emplace_back("multi-objective chain");
    if (runs(Kind::constrained_box)) out.emplace_back("constrained box");
    return out;
}

std::vector<std::string> AlgorithmEntry::encodings() const {
    std::vector<std::string> out;
    if (runs(Kind::box)) out.insert(out.end(), {"line", "free"});
    if (runs(Kind::chain)) out.emplace_back("chain");
    return out;
}

const ParamSpec* AlgorithmEntry::param(std::string_view wanted) const {
    for (const auto& p : params)
        if (p.name == wanted) return &p;
    return nullptr;
}

void AlgorithmRegistry::add(AlgorithmEntry entry) {
    if (entry.name.empty()) throw std::logic_error("an algorithm is registered without a name");
    if (find(entry.name)) throw std::logic_error("algorithm '" + entry.name + "' is registered twice");
    if (!static_cast<bool>(entry.run) || entry.kinds.empty())  // a cast, not `!`: Target may be incomplete here
        throw std::logic_error("algorithm '" + entry.name + "' is registered without a runner");
    const bool searches = entry.runs(Kind::box) || entry.runs(Kind::chain);
    if (entry.runs(Kind::multiobjective) && (searches || entry.whole_map()))
        throw std::logic_error("algorithm '" + entry.name + "' is multi-objective and runs on other kinds");
    if (entry.runs(Kind::multiobjective_chain) && !entry.runs(Kind::multiobjective))
        throw std::logic_error("algorithm '" + entry.name + "' runs on multi-objective chains only");
    if (entry.runs(Kind::constrained_box) && !entry.runs(Kind::box))
        throw std::logic_error("algorithm '" + entry.name + "' runs on constrained boxes only");
    if (entry.whole_map() && (searches || (entry.runs(Kind::grid) && entry.runs(Kind::sampled_grid))))
        throw std::logic_error("algorithm '" + entry.name + "' plans on the whole map and runs on other kinds");
    // How it plans on a grid, the same three names for every algorithm that plans through an
    // encoding (none of them has a default: the run's value is the problem's, else the native one).
    if (searches) {
        const auto encodings = entry.encodings();
        if (entry.native_encoding.empty()) entry.native_encoding = encodings.front();
        if (std::find(encodings.begin(), encodings.end(), entry.native_encoding) == encodings.end())
            throw std::logic_error("algorithm '" + entry.name + "' plans natively on " + entry.native_encoding +
                                   ", which it cannot run on");
        auto grid_choice = [](std::string name, std::vector<std::string> choices, std::string doc) {
            ParamSpec s = choice(std::move(name), choices, choices.front(), std::move(doc)).only_on_grids();
            s.no_default();
            return s;
        };
        entry.params.push_back(grid_choice("encoding", encodings,
                                           "grids: the encoding it plans through (default: the problem's, else " +
                                               entry.native_encoding + ", its native one)"));
        if (entry.runs(Kind::box))
            entry.params.push_back(grid_choice("connector", {"repair", "penalty"},
                                               "grids, line and free: how waypoints are joined (default: the "
                                               "problem's, else repair)"));
        entry.params.push_back(
            grid_choice("init", {"uniform", "walk", "rules", "sitp"},
                        "grids: its initial points or chains (default: the problem's, else its own)"));
    }
    for (std::size_t i = 0; i < entry.params.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (entry.params[i].name == entry.params[j].name)
                throw std::logic_error("algorithm '" + entry.name + "' declares parameter '" + entry.params[i].name +
                                       "' twice");
    entries_.push_back(std::move(entry));
}

const AlgorithmEntry* AlgorithmRegistry::find(std::string_view name) const {
    for (const auto& e : entries_)
        if (e.name == name) return &e;
    return nullptr;
}

const AlgorithmEntry& AlgorithmRegistry::at(std::string_view name) const {
    if (const auto* e = find(name)) return *e;
    std::string known, families;
    for (const auto& e : entries_) {
        if (e.name.find(':') == std::string::npos)
            known += (known.empty() ? "" : ", ") + e.name;
        else if (families.find(e.family + ":NAME") == std::string::npos)
            families += ", " + e.family + ":NAME";
    }
    const auto colon = name.find(':');
    if (colon != std::string_view::npos) {
        const std::string family(name.substr(0, colon));
        for (const auto& e : entries_)
            if (e.family == family)
                throw InputError("algo", "unknown algorithm '" + std::string(name) + "': the " + family +
                                             " family has no algorithm '" + std::string(name.substr(colon + 1)) +
                                             "' in this build, or it needs gradients (see the list of algorithms)");
    }
    std::vector<std::string> names;
    for (const auto& e : entries_) names.push_back(e.name);
    throw InputError("algo", "unknown algorithm '" + std::string(name) + "'" + did_you_mean(name, names) +
                                 " (known: " + known + families + ")");
}

AlgorithmRegistry& algorithms() {
    static AlgorithmRegistry registry = [] {
        AlgorithmRegistry r;
        register_builtin_algorithms(r);
        return r;
    }();
    return registry;
}

Registration::Registration(AlgorithmEntry entry) {
    algorithms().add(std::move(entry));
}

}  // namespace pride::engine
