#pragma once
// The external archive of JADE, SHADE, L-SHADE and jSO (algorithms/de.hpp): vectors the trials
// replaced, a source of x~_r2 for current-to-pbest/1 (de_mutation.hpp). One class; the papers'
// and codes' differing rules are its settings.
//
//   Zhang, J. and Sanderson, A. C. (2009). JADE. IEEE TEC 13(5), 945-958: |A| = N; each target a
//     trial strictly improved on is added; at the end of the generation random members are
//     removed until |A| <= N.
//   Tanabe, R. and Fukunaga, A. (2013). SHADE. Proc. IEEE CEC, 71-78: when the archive is full a
//     new member replaces a random one.
//   Tanabe, R. and Fukunaga, A. (2014). L-SHADE. Proc. IEEE CEC, 1658-1665, and Tanabe's code
//     (CEC 2022's lshade.cpp, version 1.0): |A| = round(2.6 N_init), then after each reduction
//     |A| = (int)(2.6 N), members past it dropped (the code; `floor_on_resize`); the code copies
//     the trial into the population before it copies "the parent" into the archive, so the archive
//     receives the successful trial (`stores_trial`; Tanabe's version 1.1 of June 2014 fixes it).
//     The paper's reading: the replaced target is archived, |A| = round(2.6 N) and random members
//     are deleted when it shrinks.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "framework/error.hpp"
#include "framework/problem.hpp"

namespace pride::de {

struct ArchiveRules {
    double rate = 0.0;                   // |A| = round(rate N_init) at the start; 0: no archive
    bool stores_trial = false;           // archive the successful trial (L-SHADE's code), not the target
    bool trim_after_generation = false;  // JADE's removal at the end of the generation
    bool floor_on_resize = false;        // L-SHADE's code: |A| = (int)(rate N) after a reduction, the last dropped

    void validate(const std::string& who) const {
        require(rate >= 0.0 && rate <= 100.0, who, "archive rate must be in [0, 100], got " + std::to_string(rate));
    }
    /// |A| for a population of n, at the start or after a reduction.
    std::size_t capacity(std::size_t n, bool initial) const noexcept {
        const double a = rate * static_cast<double>(n);
        return static_cast<std::size_t>(initial || !floor_on_resize ? std::round(a) : a);
    }
    /// Columns to allocate for a run starting from n_init.
    std::size_t storage(std::size_t n_init) const noexcept {
        const std::size_t c = capacity(n_init, true);
        return c == 0 ? 0 : c + (trim_after_generation ? n_init : 0);
    }
};

class Archive {
  public:
    Archive(std::size_t dim, std::size_t n_init, const ArchiveRules& rules)
        : rules_(rules),
          members_(static_cast<Eigen::Index>(dim), static_cast<Eigen::Index>(rules.storage(n_init))),
          capacity_(rules.capacity(n_init, true)) {}

    const Matrix& members() const noexcept { return members_; }
    std::size_t size() const noexcept { return count_; }
    std::size_t capacity() const noexcept { return capacity_; }
    std::span<const double> member(std::size_t k) const noexcept {
        return {members_.col(static_cast<Eigen::Index>(k)).data(), static_cast<std::size_t>(members_.rows())};
    }

    /// Adds x: appended while there is room (JADE: always, trimmed at the end of the generation),
    /// otherwise in place of a random member.
    template <class Draw>
    void add(std::span<const double> x, Draw& u) {
        if (capacity_ == 0) return;
        std::size_t k = count_;
        if (rules_.trim_after_generation || count_ < capacity_)
            ++count_;
        else
            k = static_cast<std::size_t>(u.below(capacity_));
        std::copy(x.begin(), x.end(), members_.col(static_cast<Eigen::Index>(k)).data());
    }

    /// JADE: random members removed until |A| <= capacity.
    template <class Draw>
    void end_generation(Draw& u) {
        while (count_ > capacity_) remove_random(u);
    }

    /// After the population shrank to n.
    template <class Draw>
    void resize(std::size_t n, Draw& u) {
        if (rules_.rate == 0.0) return;
        capacity_ = rules_.capacity(n, false);
        if (rules_.floor_on_resize)
            count_ = std::min(count_, capacity_);
        else
            while (count_ > capacity_) remove_random(u);
    }

  private:
    template <class Draw>
    void remove_random(Draw& u) {
        const auto k = static_cast<Eigen::Index>(u.below(count_));
        const auto last = static_cast<Eigen::Index>(count_ - 1);
        if (k != last) members_.col(k) = members_.col(last);
        --count_;
    }

    ArchiveRules rules_;
    Matrix members_;
    std::size_t count_ = 0;
    std::size_t capacity_ = 0;
};

}  // namespace pride::de
