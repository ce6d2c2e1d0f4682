#pragma once
// Code written once for a policy fixed at compile time or chosen at run time (a OneOf): calls f
// with the policy itself, or with the alternative the OneOf holds.
#include <utility>

namespace pride {

template <class Policy, class F>
decltype(auto) visit_policy(const Policy& policy, F&& f) {
    if constexpr (requires { policy.visit(f); })
        return policy.visit(std::forward<F>(f));
    else
        return std::forward<F>(f)(policy);
}

}  // namespace pride
