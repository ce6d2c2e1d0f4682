#include "experiment/campaign/protocol.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "framework/error.hpp"
#include "problems/continuous/cec/suites.hpp"

namespace pride::campaign {
namespace {

std::string where(const Campaign& c, int line) {
    const std::string file = c.file.empty() ? std::string("campaign") : c.file;
    return line > 0 ? fmt::format("{}:{}", file, line) : file;
}

[[noreturn]] void refuse(const Campaign& c, int line, const std::string& why) {
    throw InputError(where(c, line), fmt::format("protocol '{}': {}", c.protocol, why));
}

const engine::ContinuousSpec* continuous(const CampaignProblem& p) {
    return std::get_if<engine::ContinuousSpec>(&p.spec);
}

void bbob_2009(Campaign& c) {
    static const std::set<std::int64_t> dimensions{2, 3, 5, 10, 20, 40};
    std::map<std::pair<std::string, std::int64_t>, std::set<std::int64_t>> instances;  // (function, dim)
    for (const auto& p : c.problems) {
        const auto* f = continuous(p);
        if (p.suite != "bbob" || !f || !f->instance)
            refuse(c, p.line, fmt::format("problem '{}' is not of the [[suite]] bbob", p.id));
        if (!dimensions.count(f->dim))
            refuse(c, p.line,
                   fmt::format("problem '{}' has dimension {}; BBOB 2009 ran 2, 3, 5, 10, 20 and 40", p.id, f->dim));
        instances[{f->function, f->dim}].insert(*f->instance);
    }
    for (const auto& [key, seen] : instances)
        if (seen != std::set<std::int64_t>{1, 2, 3, 4, 5})
            refuse(c, c.protocol_line,
                   fmt::format("{} in dimension {} runs instances {}; BBOB 2009 ran instances 1-5 (the suite's "
                               "default)",
                               key.first, key.second, fmt::join(seen, ", ")));
    if (c.seeds == 0)
        c.seeds = 3;
    else if (c.seeds != 3 || !c.seed_list.empty())
        refuse(c, c.protocol_line,
               "BBOB 2009 ran 3 trials per instance (seeds 1-3): leave 'seeds' out or give seeds = 3");
    if (!c.budget.evaluations && !c.evaluations_per_dim)
        refuse(c, c.protocol_line,
               "BBOB 2009's budget was each entrant's own: give the published algorithm's in [budget] "
               "(evaluations_per_dim)");
    if (c.target) refuse(c, c.protocol_line, "BBOB 2009's targets are precisions: give [budget] precision, not target");
    if (!c.target_precision)
        c.target_precision = 1e-8;
    else if (*c.target_precision != 1e-8)
        refuse(c, c.protocol_line,
               fmt::format("BBOB 2009's final target is f_opt + 1e-8, got precision {}", *c.target_precision));
}

void cec_suite(Campaign& c) {
    const auto* rules = continuous::cec::suite_rules(c.protocol);
    for (const auto& p : c.problems)
        if (p.suite != c.protocol) refuse(c, p.line, fmt::format("problem '{}' is not of the suite", p.id));
    if (c.seeds != 0 && (c.seeds != rules->runs || !c.seed_list.empty()))
        refuse(c, c.protocol_line,
               fmt::format("the competition made {} runs per problem (seeds 1-{}): leave 'seeds' out", rules->runs,
                           rules->runs));
    if (c.budget.evaluations || c.evaluations_per_dim || c.budget.iterations)
        refuse(c, c.evaluations_line ? c.evaluations_line : c.iterations_line,
               "the competition's MaxFES is the budget: leave [budget] evaluations, evaluations_per_dim and "
               "iterations out");
}

}  // namespace

bool is_protocol(const std::string& name) {
    return name == "bbob-2009" || continuous::cec::suite_rules(name) != nullptr;
}

void apply_protocol(Campaign& c) {
    if (c.protocol.empty()) return;
    require(is_protocol(c.protocol), where(c, c.protocol_line),
            fmt::format("unknown protocol '{}' ({})", c.protocol, protocol_names));
    if (c.protocol == "bbob-2009")
        bbob_2009(c);
    else
        cec_suite(c);
}

}  // namespace pride::campaign
