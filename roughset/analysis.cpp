// The analysis of a decision table, shared by `pride roughset` and the Python module.
#include "roughset/analysis.hpp"

#include <cstdint>
#include <utility>

#include "roughset/approximation.hpp"
#include "roughset/reducts.hpp"

namespace pride::roughset {

Analysis analyse(const DecisionTable& t, std::optional<GivenRules> given) {
    Analysis a;
    a.C = t.conditions();
    a.D = t.decision();
    a.rows = t.rows();
    a.positive = positive_region(t, a.C, a.D).size();
    a.consistent = a.positive == a.rows;
    a.gamma = dependency(t, a.C, a.D);
    a.core = core(t, a.C, a.D);
    a.quick = quick_reduct(t, a.C, a.D);
    a.exhaustive = a.C.size() <= max_exhaustive_attributes;
    if (a.exhaustive) {
        a.reducts = reducts(t, a.C, a.D);
        a.used = a.reducts.front();
        a.why = a.reducts.size() == 1 ? "the only reduct" : "the first of the smallest reducts";
    } else {
        a.reducts = {a.quick};
        a.used = a.quick;
        a.why = "the QuickReduct result";
    }
    if (given) {
        a.used = std::move(given->reduct);
        a.why = std::move(given->why);
        a.rules = std::move(given->rules);
        return a;
    }
    const std::size_t distinct = indiscernibility(t, a.used).size();
    const std::string size = std::to_string(a.used.size());
    if (a.used.size() > max_exhaustive_attributes)
        a.no_rules = "not computed: the reduct has " + size + " attributes, the limit is " +
                     std::to_string(max_exhaustive_attributes);
    else if (static_cast<double>(std::uint64_t{1} << a.used.size()) * static_cast<double>(distinct) > max_rule_steps)
        a.no_rules = "not computed: 2^" + size + " value subsets x " + std::to_string(distinct) +
                     " distinct rows is over the limit of 2^28";
    else
        a.rules = minimal_rules(t, a.used, a.D);
    return a;
}

}  // namespace pride::roughset
