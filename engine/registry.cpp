#include "engine/registry.hpp"

#include <stdexcept>

#include "framework/error.hpp"

namespace pride::engine {

void register_builtin_algorithms(AlgorithmRegistry& registry);  // made by CMake from engine/algorithms/

std::vector<std::string> AlgorithmEntry::spaces() const {
    std::vector<std::string> out;
    if (run_box) out.emplace_back("box");
    if (run_chain) out.emplace_back("chain");
    if (solve_grid) out.emplace_back("grid");
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
    if (!entry.run_box && !entry.run_chain && !entry.solve_grid)
        throw std::logic_error("algorithm '" + entry.name + "' is registered without a runner");
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
    throw InputError("algo", "unknown algorithm '" + std::string(name) + "' (known: " + known + families + ")");
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
