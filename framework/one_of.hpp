#pragma once
// OneOf<P...>: a policy that is one of several policies, chosen at run time. For choices made once
// per iteration or per run (PSO's velocity rule, the GA's replacement, ILSO's weight), which cost
// nothing measurable per evaluation, so one instantiation of a skeleton carries a family's
// variants (pso and pso-constriction, ga and ga-plus, lso and ilso). Each alternative stays a
// policy type of its own, usable alone at compile time.
#include <utility>
#include <variant>

namespace pride {

template <class... Policies>
class OneOf {
  public:
    OneOf() = default;  // the first alternative, default-constructed
    template <class P>
    requires(std::is_same_v<std::decay_t<P>, Policies> || ...) OneOf(P&& policy)
        : policy_(std::forward<P>(policy)) {}  // NOLINT: a policy converts implicitly

    template <class P>
    bool holds() const noexcept {
        return std::holds_alternative<P>(policy_);
    }
    template <class P>
    P& get() {
        return std::get<P>(policy_);
    }
    template <class P>
    const P& get() const {
        return std::get<P>(policy_);
    }

    template <class F>
    decltype(auto) visit(F&& f) const {
        return std::visit(std::forward<F>(f), policy_);
    }
    template <class F>
    decltype(auto) visit(F&& f) {
        return std::visit(std::forward<F>(f), policy_);
    }

    /// The chosen policy's call (every alternative must return the same type).
    template <class... Args>
    decltype(auto) operator()(Args&&... args) const {
        return std::visit([&](const auto& p) -> decltype(auto) { return p(std::forward<Args>(args)...); }, policy_);
    }

    template <class... Args>
    void validate(const Args&... args) const {
        std::visit([&](const auto& p) { p.validate(args...); }, policy_);
    }

  private:
    std::variant<Policies...> policy_;
};

}  // namespace pride
