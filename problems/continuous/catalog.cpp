// The catalog: every function by name, with its dimensions and instances (catalog.hpp). The
// classes themselves are held by continuous::Function (function_variant.hpp, function.cpp).
#include "problems/continuous/catalog.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "framework/close_names.hpp"
#include "framework/error.hpp"
#include "problems/continuous/bbob/instance.hpp"
#include "problems/continuous/bbob_mixint/bbob_mixint.hpp"
#include "problems/continuous/function_variant.hpp"
#include "problems/continuous/integer_variables.hpp"

namespace pride::continuous {

using detail::Any;

namespace {

template <class Held>
Function wrap(Held held, std::string name, std::int64_t instance) {
    auto impl = std::make_unique<Function::Impl>(
        Function::Impl{Any(std::in_place_type<Held>, std::move(held)), std::move(name), instance});
    return Function(std::move(impl));
}

template <class F>
F build(std::size_t dim, const FunctionInfo* info) {
    if constexpr (std::is_constructible_v<F, std::size_t, const FunctionInfo&>)
        return info ? F(dim, *info) : F(dim);
    else
        return F(dim);
}

std::string number_text(double v) {
    std::string s = std::to_string(v);
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

/// "Yao et al. 1999 F17: branin on [-5, 10] x [0, 15]": the formula's name and the box, read off
/// the function itself (Branin's differs per coordinate).
template <class F>
std::string yao_summary(int number, std::string_view function, const FunctionInfo* info) {
    const std::size_t dim = F::info.fixed_dim ? F::info.fixed_dim : F::info.min_dim;
    const F f = build<F>(dim, info);
    std::string box;
    for (std::size_t i = 0; i < f.dimension(); ++i) {
        const std::string side = "[" + number_text(f.lower()[i]) + ", " + number_text(f.upper()[i]) + "]";
        if (F::info.fixed_dim == 0) {
            box = side + "^D";
            break;
        }
        box += (i ? " x " : "") + side;
    }
    return "Yao et al. 1999 F" + std::to_string(number) + ": " + std::string(function) + " on " + box;
}

/// A scalable function: instance 0 as defined, k >= 1 through instance_transform(). `info`: a
/// static table other than F's own (Yao's box for the same formula), never a copy, since the
/// function keeps a pointer to it.
template <class F>
CatalogEntry scalable(std::string name, const FunctionInfo* info = nullptr) {
    CatalogEntry e;
    e.min_dim = F::info.min_dim;
    e.make = [name, info](std::size_t dim, std::int64_t instance) {
        F f = build<F>(dim, info);
        if (instance == 0) return wrap(std::move(f), name, 0);
        auto anchor = f.optimum_point();
        const bool bounded = F::info.bounded_domain;  // a property of the formula, whatever the box
        const auto lo = f.lower(), hi = f.upper();
        Transform t = instance_transform(lo, hi, std::move(anchor), static_cast<std::uint64_t>(instance), bounded);
        return wrap(Transformed<F>(std::move(f), std::move(t), name), name, instance);
    };
    return e;
}

/// shifted-NAME: F under the fixed golden-ratio shift (instance.hpp), instance 0 only.
template <class F>
CatalogEntry shifted() {
    CatalogEntry e;
    e.min_dim = F::info.min_dim;
    e.instances = Instances::none;
    e.make = [](std::size_t dim, std::int64_t) {
        Shifted<F> s(dim);
        return wrap(static_cast<Transformed<F>>(std::move(s)), "shifted-" + std::string(F::info.name), 0);
    };
    return e;
}

/// A fixed-dimension function (Yao's F14-F23): its one dimension, instance 0 only.
template <class F>
CatalogEntry fixed(std::string name) {
    CatalogEntry e;
    e.min_dim = F::info.fixed_dim;
    e.fixed_dim = F::info.fixed_dim;
    e.instances = Instances::none;
    e.make = [name](std::size_t dim, std::int64_t) { return wrap(F(dim), name, 0); };
    return e;
}

template <class F>
CatalogEntry entry_for(std::string name, const FunctionInfo* info = nullptr) {
    if constexpr (F::info.fixed_dim != 0)
        return fixed<F>(std::move(name));
    else
        return scalable<F>(std::move(name), info);
}

template <class F>
void add(Registry<CatalogEntry>& r) {
    r.add(std::string(F::info.name), std::string(F::info.summary), entry_for<F>(std::string(F::info.name)));
}

/// yao-fN: Yao, Liu and Lin (1999), Table I, function N: the class F with the table `info` (Yao's
/// box where it differs from the plain name's: F1, F5, F10).
template <class F>
void add_yao(Registry<CatalogEntry>& r, int number, const FunctionInfo* info = nullptr) {
    const YaoEntry& y = yao_table[static_cast<std::size_t>(number - 1)];
    const FunctionInfo& table = info ? *info : F::info;
    require(y.function == F::info.name && y.info == &table, "catalog",
            "yao_table disagrees at F" + std::to_string(number));
    const std::string alias(y.alias);
    CatalogEntry e = entry_for<F>(alias, info);
    e.suite = "classic";
    e.number = number;
    r.add(alias, yao_summary<F>(number, y.function, info), std::move(e));
}

template <class F>
void add_scalable(Registry<CatalogEntry>& r, bool with_shift) {
    r.add(std::string(F::info.name), std::string(F::info.summary), scalable<F>(std::string(F::info.name)));
    if (with_shift)
        r.add("shifted-" + std::string(F::info.name),
              std::string(F::info.name) + " with its optimum moved off the centre (instance.hpp: shift_optimum)",
              shifted<F>());
}

/// bbob-fN: COCO's function N, instances from 1 (the class builds its own instance).
template <class F>
void add_bbob(Registry<CatalogEntry>& r) {
    CatalogEntry e;
    e.min_dim = F::info.min_dim;
    e.instances = Instances::coco;
    e.suite = "bbob";
    e.number = F::id;
    e.make = [](std::size_t dim, std::int64_t instance) {
        return wrap(F(dim, instance), std::string(F::info.name), instance);
    };
    r.add(std::string(F::info.name), "BBOB " + std::string(F::info.summary) + "; COCO's instances", std::move(e));
}

template <class... F>
void add_bbob_suite(Registry<CatalogEntry>& r, std::tuple<F...>*) {
    (add_bbob<F>(r), ...);
}

/// bbob-mixint-fN: COCO's mixed-integer function N (bbob-fN with integer variables), in its
/// dimensions below the largescale ones (bbob_mixint.hpp), instances from 1.
template <class F>
void add_bbob_mixint(Registry<CatalogEntry>& r) {
    CatalogEntry e;
    for (std::size_t d = bbob_mixint::kMinDimension; d <= bbob_mixint::kMaxDimension; d += 5) e.dims.push_back(d);
    e.min_dim = e.dims.front();
    e.instances = Instances::coco;
    e.suite = "bbob-mixint";
    e.number = F::id;
    e.make = [](std::size_t dim, std::int64_t instance) {
        return wrap(bbob_mixint::Problem(F::id, dim, instance), bbob_mixint::name_of(F::id), instance);
    };
    r.add(bbob_mixint::name_of(F::id),
          "COCO bbob-mixint: BBOB " + std::string(F::info.summary) +
              " with 4D/5 integer variables (2, 4, 8, 16 values); COCO's instances",
          std::move(e));
}

template <class... F>
void add_bbob_mixint_suite(Registry<CatalogEntry>& r, std::tuple<F...>*) {
    (add_bbob_mixint<F>(r), ...);
}

/// cecYYYY-fN: the CEC suites' functions, in the dimensions of the official data, one instance.
void add_cec_suite(Registry<CatalogEntry>& r, cec::Suite suite) {
    for (int k = 1; k <= cec::size(suite); ++k) {
        const FunctionInfo& info = cec::info(suite, k);
        CatalogEntry e;
        e.dims = cec::dimensions(suite, k);
        e.min_dim = e.dims.front();
        e.instances = Instances::none;
        e.suite = std::string(cec::suite_name(suite));
        e.number = k;
        e.make = [suite, k](std::size_t dim, std::int64_t) {
            return wrap(cec::CecFunction(suite, k, dim), std::string(cec::info(suite, k).name), 0);
        };
        r.add(std::string(info.name),
              std::string(info.summary) + "; the official data (" + std::string(cec::data_variable(suite)) + ")",
              std::move(e));
    }
}

}  // namespace

const Registry<CatalogEntry>& catalog() {
    static const Registry<CatalogEntry> r = [] {
        Registry<CatalogEntry> reg;
        add_scalable<Sphere>(reg, true);
        add_scalable<Rastrigin>(reg, true);
        add_scalable<Rosenbrock>(reg, true);
        add_scalable<Ackley>(reg, true);
        add_scalable<Griewank>(reg, true);
        // Schwefel is not shifted: its optimum is already off the centre, and a shifted argument
        // would leave [-500, 500], where the formula has lower values than its "optimum" (its
        // instances k >= 1 clamp the argument instead: instance.hpp).
        add_scalable<Schwefel>(reg, false);
        // Yao et al. (1999)'s functions under their own names, then the extras.
        add<Schwefel222>(reg);
        add<Schwefel12>(reg);
        add<Schwefel221>(reg);
        add<Step>(reg);
        add<QuarticNoise>(reg);
        add<Schwefel226>(reg);
        add<Penalized1>(reg);
        add<Penalized2>(reg);
        add<ShekelFoxholes>(reg);
        add<Kowalik>(reg);
        add<SixHumpCamel>(reg);
        add<Branin>(reg);
        add<GoldsteinPrice>(reg);
        add<Hartman3>(reg);
        add<Hartman6>(reg);
        add<Shekel5>(reg);
        add<Shekel7>(reg);
        add<Shekel10>(reg);
        add<Ellipsoid>(reg);
        add<Levy>(reg);
        add<Zakharov>(reg);
        add<StyblinskiTang>(reg);
        // The F numbers of the swarm literature (Yao et al. 1999, Table I).
        add_yao<Sphere>(reg, 1, &yao_f1_info);
        add_yao<Schwefel222>(reg, 2);
        add_yao<Schwefel12>(reg, 3);
        add_yao<Schwefel221>(reg, 4);
        add_yao<Rosenbrock>(reg, 5, &yao_f5_info);
        add_yao<Step>(reg, 6);
        add_yao<QuarticNoise>(reg, 7);
        add_yao<Schwefel226>(reg, 8);
        add_yao<Rastrigin>(reg, 9);
        add_yao<Ackley>(reg, 10, &yao_f10_info);
        add_yao<Griewank>(reg, 11);
        add_yao<Penalized1>(reg, 12);
        add_yao<Penalized2>(reg, 13);
        add_yao<ShekelFoxholes>(reg, 14);
        add_yao<Kowalik>(reg, 15);
        add_yao<SixHumpCamel>(reg, 16);
        add_yao<Branin>(reg, 17);
        add_yao<GoldsteinPrice>(reg, 18);
        add_yao<Hartman3>(reg, 19);
        add_yao<Hartman6>(reg, 20);
        add_yao<Shekel5>(reg, 21);
        add_yao<Shekel7>(reg, 22);
        add_yao<Shekel10>(reg, 23);
        add_bbob_suite(reg, static_cast<bbob::All*>(nullptr));
        add_bbob_mixint_suite(reg, static_cast<bbob::All*>(nullptr));
        add_cec_suite(reg, cec::Suite::y2017);
        add_cec_suite(reg, cec::Suite::y2022);
        return reg;
    }();
    return r;
}

std::int64_t default_instance(const CatalogEntry& entry) {
    return entry.instances == Instances::coco ? 1 : 0;
}

Function make_function(std::string_view name, std::int64_t dim, std::optional<std::int64_t> instance,
                       const std::string& dim_source) {
    const auto* item = catalog().find(name);
    if (!item) {
        std::vector<std::string> names;
        for (const auto& known : catalog().items()) names.push_back(known.name);
        throw InputError("problem", "unknown problem '" + std::string(name) + "'" + did_you_mean(name, names));
    }
    const auto& e = item->entry;
    require(dim >= 1, dim_source, "dimension must be >= 1, got " + std::to_string(dim));
    // bbob-mixint's dimensions are COCO's multiples of 5, below its largescale ones: said in full.
    if (e.suite == "bbob-mixint" &&
        std::find(e.dims.begin(), e.dims.end(), static_cast<std::size_t>(dim)) == e.dims.end())
        throw InputError(dim_source, bbob_mixint::dimension_message(e.number, dim));
    require(static_cast<std::size_t>(dim) >= e.min_dim, dim_source,
            std::string(name) + " needs dimension >= " + std::to_string(e.min_dim) + ", got " + std::to_string(dim));
    require(e.fixed_dim == 0 || static_cast<std::size_t>(dim) == e.fixed_dim, dim_source,
            std::string(name) + " is defined in dimension " + std::to_string(e.fixed_dim) + " only, got " +
                std::to_string(dim));
    if (!e.dims.empty() && std::find(e.dims.begin(), e.dims.end(), static_cast<std::size_t>(dim)) == e.dims.end()) {
        std::string list;
        for (const std::size_t d : e.dims) list += (list.empty() ? "" : ", ") + std::to_string(d);
        throw InputError(dim_source,
                         std::string(name) + " is defined in dimensions " + list + " only, got " + std::to_string(dim));
    }
    const std::int64_t k = instance.value_or(default_instance(e));
    switch (e.instances) {
        case Instances::transform:
            require(k >= 0, "instance", "must be >= 0, got " + std::to_string(k));
            break;
        case Instances::none:
            require(k == 0 || !e.suite.starts_with("cec"), "instance",
                    std::string(name) + ": CEC functions have no instances (the official data fixes one function)");
            require(k == 0, "instance",
                    std::string(name) + " has one instance only (0)" +
                        (name.starts_with("shifted-") ? "; use " + std::string(name.substr(8)) + " --instance K" : ""));
            break;
        case Instances::coco:
            require(k >= 1, "instance",
                    std::string(name) + ": COCO numbers instances from 1, got " + std::to_string(k));
            require(k <= bbob::kMaxInstance, "instance", bbob::instance_range_message(name, k));
            break;
    }
    return e.make(static_cast<std::size_t>(dim), k);
}

std::size_t integer_variables(const Function& f) noexcept {
    std::size_t count = 0;
    for (std::size_t i = 0; i < f.dimension(); ++i) count += f.variable_type(i) == VariableType::integer ? 1 : 0;
    return count;
}

}  // namespace pride::continuous
