#pragma once
// The continuous problems by name, for the command line, the benchmarks and campaigns. A problem
// is returned as a std::variant of the concrete types, so a run visits it once and then executes
// fully typed code: no virtual call per evaluation.
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

#include "framework/error.hpp"
#include "framework/registry.hpp"
#include "problems/continuous/functions.hpp"
#include "problems/continuous/shifted.hpp"

namespace pride::continuous {

using AnyProblem = std::variant<Sphere, Rastrigin, Rosenbrock, Ackley, Griewank, Schwefel, Shifted<Sphere>,
                                Shifted<Rastrigin>, Shifted<Rosenbrock>, Shifted<Ackley>, Shifted<Griewank>>;

struct CatalogEntry {
    std::size_t min_dim;
    AnyProblem (*make)(std::size_t dim);
};

namespace detail {
template <class F>
AnyProblem make(std::size_t dim) {
    return AnyProblem(std::in_place_type<F>, dim);
}
template <class F, bool with_shift>
void add_plain_and_shifted(Registry<CatalogEntry>& r) {
    r.add(std::string(F::info.name), std::string(F::info.summary), CatalogEntry{F::info.min_dim, &make<F>});
    if constexpr (with_shift)
        r.add("shifted-" + std::string(F::info.name),
              std::string(F::info.name) + " with its optimum moved off the centre (see shifted.hpp)",
              CatalogEntry{F::info.min_dim, &make<Shifted<F>>});
}
}  // namespace detail

inline const Registry<CatalogEntry>& catalog() {
    static const Registry<CatalogEntry> r = [] {
        Registry<CatalogEntry> reg;
        detail::add_plain_and_shifted<Sphere, true>(reg);
        detail::add_plain_and_shifted<Rastrigin, true>(reg);
        detail::add_plain_and_shifted<Rosenbrock, true>(reg);
        detail::add_plain_and_shifted<Ackley, true>(reg);
        detail::add_plain_and_shifted<Griewank, true>(reg);
        // Schwefel is not shifted: its optimum is already off the centre, and a shifted argument
        // would leave [-500, 500], where the formula has lower values than its "optimum".
        detail::add_plain_and_shifted<Schwefel, false>(reg);
        return reg;
    }();
    return r;
}

/// The problem `name` in dimension `dim`; InputError for an unknown name or a bad dimension, the
/// latter blamed on `dim_source` (the option or input the dimension came from).
inline AnyProblem make_problem(std::string_view name, std::int64_t dim, const std::string& dim_source = "dim") {
    const auto* item = catalog().find(name);
    require(item != nullptr, "problem", "unknown problem '" + std::string(name) + "'");
    require(dim >= 1, dim_source, "dimension must be >= 1, got " + std::to_string(dim));
    require(static_cast<std::size_t>(dim) >= item->entry.min_dim, dim_source,
            std::string(name) + " needs dimension >= " + std::to_string(item->entry.min_dim) + ", got " +
                std::to_string(dim));
    return item->entry.make(static_cast<std::size_t>(dim));
}

}  // namespace pride::continuous
