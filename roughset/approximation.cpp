// Lower and upper approximations, boundaries, positive regions and dependency.
#include "roughset/approximation.hpp"

#include <string>
#include <vector>

#include "roughset/partition.hpp"

namespace pride::roughset {

using namespace detail;

Classes indiscernibility(const DecisionTable& t, const Attributes& B) {
    return classes_of(partition_of(t, checked(t, B, "B")));
}

namespace {
/// The union of the B-classes that lie inside X (`inside`: the lower approximation) or meet X
/// (the upper one).
Objects approximation(const DecisionTable& t, const Attributes& B, const Objects& X, bool inside) {
    const auto in = membership(t, X);
    const auto member = [&](std::size_t x) { return in[x] != 0; };
    Objects out;
    for (const auto& cls : indiscernibility(t, B))
        if (inside ? std::all_of(cls.begin(), cls.end(), member) : std::any_of(cls.begin(), cls.end(), member))
            out.insert(out.end(), cls.begin(), cls.end());
    std::sort(out.begin(), out.end());
    return out;
}
}  // namespace

Objects lower_approximation(const DecisionTable& t, const Attributes& B, const Objects& X) {
    return approximation(t, B, X, true);
}

Objects upper_approximation(const DecisionTable& t, const Attributes& B, const Objects& X) {
    return approximation(t, B, X, false);
}

Objects boundary(const DecisionTable& t, const Attributes& B, const Objects& X) {
    const Objects up = upper_approximation(t, B, X), low = lower_approximation(t, B, X);
    Objects out;
    std::set_difference(up.begin(), up.end(), low.begin(), low.end(), std::back_inserter(out));
    return out;
}

Objects positive_region(const DecisionTable& t, const Attributes& C, const Attributes& D) {
    const Collapsed rows(t, checked(t, C, "C"), checked(t, D, "D"));
    Objects out;
    for (std::size_t r = 0; r < t.rows(); ++r)
        if (rows.gd[rows.of_object[r]] != rows.conflict) out.push_back(r);
    return out;
}

double dependency(const DecisionTable& t, const Attributes& C, const Attributes& D) {
    if (t.rows() == 0) return 1.0;
    return static_cast<double>(positive_region(t, C, D).size()) / static_cast<double>(t.rows());
}

bool consistent(const DecisionTable& t, const Attributes& C, const Attributes& D) {
    return positive_region(t, C, D).size() == t.rows();
}

}  // namespace pride::roughset
