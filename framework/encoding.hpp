#pragma once
// Encodings: the map from an algorithm's genotype (a point in a box) to a problem's solution (a
// vector, a path). Composing a problem with an encoding gives a BoxProblem, so an algorithm never
// learns what it is really searching: PSO on the grid is PSO on Encoded<GridProblem, LineEncoding>.
//
// An encoding E for a problem P provides, with P passed in (never held by reference):
//   dimension(p), lower(p), upper(p)  the genotype box;
//   decode(p, genotype)               the solution, which p.evaluate(...) turns into the minimised value.
// The decoded solution may be a reference to a buffer inside the encoding (no allocation per
// evaluation); it is valid until the next decode.
#include <span>
#include <utility>

#include "framework/problem.hpp"

namespace pride {

template <class E, class P>
concept EncodingFor = std::copy_constructible<E> && requires(E& e, const E& ce, P& p, std::span<const double> g) {
    { ce.dimension(p) } -> std::convertible_to<std::size_t>;
    { ce.lower(p) } -> std::convertible_to<std::span<const double>>;
    { ce.upper(p) } -> std::convertible_to<std::span<const double>>;
    { p.evaluate(e.decode(p, g)) } -> std::convertible_to<double>;
};

/// The identity encoding of a box problem: the genotype is the solution.
struct IdentityEncoding {
    template <class P>
    std::size_t dimension(const P& p) const {
        return p.dimension();
    }
    template <class P>
    std::span<const double> lower(const P& p) const {
        return p.lower();
    }
    template <class P>
    std::span<const double> upper(const P& p) const {
        return p.upper();
    }
    template <class P>
    std::span<const double> decode(const P&, std::span<const double> g) const {
        return g;
    }
};

/// A problem seen through an encoding; itself a BoxProblem.
template <class P, class E>
requires EncodingFor<E, P>
class Encoded {
  public:
    Encoded(P problem, E encoding) : problem_(std::move(problem)), encoding_(std::move(encoding)) {}

    std::size_t dimension() const { return encoding_.dimension(problem_); }
    std::span<const double> lower() const { return encoding_.lower(problem_); }
    std::span<const double> upper() const { return encoding_.upper(problem_); }
    double evaluate(std::span<const double> g) { return problem_.evaluate(encoding_.decode(problem_, g)); }

    /// The solution a genotype stands for (valid until the next call).
    decltype(auto) decode(std::span<const double> g) { return encoding_.decode(problem_, g); }

    const P& problem() const { return problem_; }
    const E& encoding() const { return encoding_; }

    /// Forwards the problem's own suggestions when the encoding can turn them into genotypes.
    void starting_points(Rng& rng, Matrix& out) const requires requires(const E& e, const P& p, Rng& r, Matrix& m) {
        e.starting_points(p, r, m);
    }
    { encoding_.starting_points(problem_, rng, out); }

  private:
    P problem_;
    E encoding_;
};

}  // namespace pride
