#pragma once
// The multi-objective box problems by name: ZDT1-4, 6, DTLZ1-7 and WFG1-9 as one type, so that
// each multi-objective algorithm is compiled once for all of them (as continuous::Function is one
// type for the single-objective catalog). The problem is chosen once, when it is built; a batch
// dispatches once, a single point once per evaluation (a switch over the variant's cases, no virtual call).
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include "framework/error.hpp"
#include "framework/problem.hpp"
#include "problems/multiobjective/dtlz.hpp"
#include "problems/multiobjective/fronts.hpp"
#include "problems/multiobjective/wfg.hpp"
#include "problems/multiobjective/zdt.hpp"

namespace pride::multiobjective {

struct CatalogEntry {
    std::string_view name;
    std::string_view summary;
    std::size_t variables;   // the paper's n (ZDT), k, the distance variables (DTLZ), n at the default M (WFG)
    std::size_t objectives;  // the default M (ZDT: always 2)
};

/// Every problem Benchmark builds, with its defaults (zdt.hpp's, dtlz.hpp's and wfg.hpp's tables).
inline constexpr std::array<CatalogEntry, 21> kCatalog{{
    {"zdt1", "ZDT T1: convex front f2 = 1 - sqrt(f1), n = 30", 30, 2},
    {"zdt2", "ZDT T2: concave front f2 = 1 - f1^2, n = 30", 30, 2},
    {"zdt3", "ZDT T3: five disconnected pieces, n = 30", 30, 2},
    {"zdt4", "ZDT T4: 21^9 local fronts (multimodal g), n = 10", 10, 2},
    {"zdt6", "ZDT T6: non-uniform, biased, concave, n = 10", 10, 2},
    {"dtlz1", "DTLZ1: linear front sum f = 0.5, multimodal g, k = 5", 5, 3},
    {"dtlz2", "DTLZ2: spherical front, k = 10", 10, 3},
    {"dtlz3", "DTLZ3: spherical front, multimodal g, k = 10", 10, 3},
    {"dtlz4", "DTLZ4: spherical front, biased density (alpha 100), k = 10", 10, 3},
    {"dtlz5", "DTLZ5: degenerate front (a curve), k = 10", 10, 3},
    {"dtlz6", "DTLZ6: degenerate front, harder g, k = 10", 10, 3},
    {"dtlz7", "DTLZ7: 2^(M-1) disconnected regions, k = 20", 20, 3},
    {"wfg1", "WFG1: convex and mixed front, flat and polynomial bias, k = 2(M-1), l = 20", 24, 3},
    {"wfg2", "WFG2: convex, disconnected front, non-separable, k = 2(M-1), l = 20", 24, 3},
    {"wfg3", "WFG3: linear, degenerate front, non-separable, k = 2(M-1), l = 20", 24, 3},
    {"wfg4", "WFG4: concave front, multimodal, k = 2(M-1), l = 20", 24, 3},
    {"wfg5", "WFG5: concave front, deceptive, k = 2(M-1), l = 20", 24, 3},
    {"wfg6", "WFG6: concave front, non-separable, k = 2(M-1), l = 20", 24, 3},
    {"wfg7", "WFG7: concave front, parameter-dependent bias, k = 2(M-1), l = 20", 24, 3},
    {"wfg8", "WFG8: concave front, parameter-dependent bias, non-separable, k = 2(M-1), l = 20", 24, 3},
    {"wfg9", "WFG9: concave front, parameter-dependent, multimodal, deceptive, k = 2(M-1), l = 20", 24, 3},
}};

/// The entry of `name`, or nullptr.
inline const CatalogEntry* find_problem(std::string_view name) {
    for (const auto& e : kCatalog)
        if (e.name == name) return &e;
    return nullptr;
}

/// The catalog's names, comma-separated (for messages).
inline std::string problem_names() {
    std::string names;
    for (const auto& c : kCatalog) names += (names.empty() ? "" : ", ") + std::string(c.name);
    return names;
}

/// One of the catalog's problems, chosen by name at construction.
class Benchmark {
  public:
    /// `variables` n (0: the paper's default: n for ZDT, M + k - 1 with the default k for DTLZ,
    /// k + l with k = 2 (M - 1) and l = 20 for WFG); `objectives` M (0: the default, 2 for ZDT and 3
    /// for DTLZ and WFG). WFG: n = k + l with k = 2 (M - 1), so l = n - k. InputError naming `where`
    /// for an unknown name, an M the problem does not have, an n below M for DTLZ, or an n <= k (or
    /// an odd l for WFG2 and WFG3) for WFG.
    Benchmark(std::string_view name, std::size_t variables = 0, std::size_t objectives = 0,
              std::string_view where = "problem")
        : problem_(make(name, variables, objectives, where)) {}

    std::string_view name() const {
        return std::visit([](const auto& p) { return std::string_view(p.name()); }, problem_);
    }
    std::size_t dimension() const {
        return std::visit([](const auto& p) { return p.dimension(); }, problem_);
    }
    std::span<const double> lower() const {
        return std::visit([](const auto& p) { return p.lower(); }, problem_);
    }
    std::span<const double> upper() const {
        return std::visit([](const auto& p) { return p.upper(); }, problem_);
    }
    std::size_t objectives() const {
        return std::visit([](const auto& p) { return p.objectives(); }, problem_);
    }

    void evaluate(std::span<const double> x, std::span<double> f) const {
        std::visit([&](const auto& p) { p.evaluate(x, f); }, problem_);
    }
    /// Every column of `points` into the same column of `values` (M rows): one dispatch per batch.
    void evaluate_batch(MatrixView points, Matrix& values) const {
        std::visit(
            [&](const auto& p) {
                const auto m = p.objectives();
                const auto n = static_cast<std::size_t>(points.rows());
                for (Eigen::Index j = 0; j < points.cols(); ++j)
                    p.evaluate(std::span<const double>(points.col(j).data(), n),
                               std::span<double>(values.col(j).data(), m));
            },
            problem_);
    }

    /// The analytic front sampled with (at most) `points` points (fronts.hpp's reference_front).
    Matrix reference_front(std::size_t points) const {
        if (const auto* w = std::get_if<Wfg>(&problem_)) return wfg_reference_front(w->problem(), objectives(), points);
        return multiobjective::reference_front(name(), objectives(), points);
    }

  private:
    using Any = std::variant<Zdt1, Zdt2, Zdt3, Zdt4, Zdt6, Dtlz1, Dtlz2, Dtlz3, Dtlz4, Dtlz5, Dtlz6, Dtlz7, Wfg>;

    static Any make(std::string_view name, std::size_t n, std::size_t m, std::string_view where) {
        const CatalogEntry* e = find_problem(name);
        if (e == nullptr)
            throw InputError(std::string(where), "unknown multi-objective problem '" + std::string(name) +
                                                     "' (known: " + problem_names() + ")");
        const std::string w(name);
        if (name.starts_with("zdt")) {
            require(m == 0 || m == 2, w, "has 2 objectives, got " + std::to_string(m));
            const std::size_t v = n == 0 ? e->variables : n;
            if (name == "zdt1") return Zdt1(v);
            if (name == "zdt2") return Zdt2(v);
            if (name == "zdt3") return Zdt3(v);
            if (name == "zdt4") return Zdt4(v);
            return Zdt6(v);
        }
        const std::size_t mm = m == 0 ? e->objectives : m;
        if (name.starts_with("wfg")) {
            require(mm >= 2 && mm <= kMaxObjectives, w,
                    "needs 2 <= M <= " + std::to_string(kMaxObjectives) + " objectives, got " + std::to_string(mm));
            const std::size_t k = 2 * (mm - 1);
            require(n == 0 || n > k, w,
                    "needs n > k = 2 (M - 1) = " + std::to_string(k) + " variables (l = n - k >= 1), got " +
                        std::to_string(n));
            return Wfg(name[3] - '0', mm, k, n == 0 ? 0 : n - k);
        }
        require(mm >= 2 && mm <= kMaxObjectives, w,
                "needs 2 <= M <= " + std::to_string(kMaxObjectives) + " objectives, got " + std::to_string(mm));
        require(n == 0 || n >= mm, w,
                "needs n >= M = " + std::to_string(mm) + " variables (k = n - M + 1 >= 1), got " + std::to_string(n));
        const std::size_t k = n == 0 ? e->variables : n - mm + 1;
        switch (name[4]) {
            case '1':
                return Dtlz1(mm, k);
            case '2':
                return Dtlz2(mm, k);
            case '3':
                return Dtlz3(mm, k);
            case '4':
                return Dtlz4(mm, k);
            case '5':
                return Dtlz5(mm, k);
            case '6':
                return Dtlz6(mm, k);
            default:
                return Dtlz7(mm, k);
        }
    }

    Any problem_;
};

}  // namespace pride::multiobjective
