#pragma once
// What a run keeps of its progress for COCO's data files: (evaluations, best so far) whenever the
// precision best - f_opt crosses one of COCO's target triggers (its .dat file) and at COCO's
// evaluation triggers (its .tdat file). The triggers are those of COCO's bbob logger
// (numbbo/coco-experiment, src/coco_observer.c and src/logger_bbob.c, default options):
// - targets: 20 per decade, log10(precision) rounded up to a multiple of 1/20, precisions below
//   1e-8 taken as 1e-8 (0 as 1e-9), negative ones on a mirrored scale; the first evaluation is
//   always kept (without moving the trigger, as COCO's logger does);
// - evaluations: floor(10^(k/20)) for k = 0, 1, ... and dim * {1, 2, 5} * 10^k.
// Bounded by the decades crossed (a few hundred points), never by the evaluations.
// On a constrained problem COCO counts f evaluations and constraint evaluations apart and its
// evaluation triggers follow their sum: after count_constraints(), an evaluation (f and all g_i)
// counts twice for the triggers, while the points keep the number of evaluations.
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pride {

struct TracePoint {
    std::int64_t evaluations = 0;
    double best = 0.0;  // the best value after those evaluations (raw f, not the precision)
    friend bool operator==(const TracePoint&, const TracePoint&) = default;
};

class CocoTrace {
  public:
    static constexpr int kTargetsPerDecade = 20;      // number_target_triggers
    static constexpr int kEvaluationsPerDecade = 20;  // number_evaluation_triggers
    static constexpr double kPrecision = 1e-8;        // log_target_precision

    /// `reference`: f_opt when known, else 0 (the triggers then follow the values themselves).
    explicit CocoTrace(double reference = 0.0, std::size_t dimension = 1)
        : reference_(reference), dimension_(static_cast<std::int64_t>(dimension == 0 ? 1 : dimension)) {
        next_second_ = dimension_ * kBases[0];
        next_ = std::min(next_first_, next_second_);
    }

    /// After every evaluation (whole or partial; `evaluations` counts it), with the best value so
    /// far and whether this evaluation improved it.
    /// Inline and two compares in the common case (no improvement, no trigger): it runs at every
    /// evaluation of every run.
    void record(std::int64_t evaluations, double best, bool improved) {
        if (improved || evaluations == 1) [[unlikely]]
            target_record(evaluations, best);
        if (evaluations * weight_ >= next_) [[unlikely]]
            evaluation_trigger(evaluations, best);
    }

    /// From now on an evaluation is one f and one constraint evaluation for the evaluation
    /// triggers (COCO's f evaluations + g evaluations). Call before the first record().
    void count_constraints() noexcept { weight_ = 2; }

    /// The run's end (logger_bbob_free): a last point at `evaluations` in each trace whose last
    /// point is not there.
    void close(std::int64_t evaluations, double best) {
        for (auto* points : {&targets_, &evaluations_})
            if (points->empty() || points->back().evaluations != evaluations) points->push_back({evaluations, best});
    }

    std::vector<TracePoint>& targets() noexcept { return targets_; }
    std::vector<TracePoint>& evaluations() noexcept { return evaluations_; }

  private:
    [[gnu::noinline]] void target_record(std::int64_t evaluations, double best) {
        if (evaluations == 1)  // COCO logs the first evaluation without moving the target trigger
            targets_.push_back({evaluations, best});
        else if (target_trigger(best - reference_))
            targets_.push_back({evaluations, best});
    }

    [[gnu::noinline]] void evaluation_trigger(std::int64_t evaluations, double best) {
        const std::int64_t counted = evaluations * weight_;
        bool hit = false;
        if (counted >= next_first_) {  // coco_observer_evaluations_trigger_first
            while (first_value(exponent1_) <= next_first_) ++exponent1_;
            next_first_ = first_value(exponent1_);
            hit = true;
        }
        if (counted >= next_second_) {  // coco_observer_evaluations_trigger_second
            if (base_ + 1 < std::size(kBases)) {
                ++base_;
            } else {
                base_ = 0;
                ++exponent2_;
            }
            next_second_ =
                static_cast<std::int64_t>(std::pow(10.0, static_cast<double>(exponent2_)) *
                                          static_cast<double>(dimension_) * static_cast<double>(kBases[base_]));
            hit = true;
        }
        if (hit) evaluations_.push_back({evaluations, best});
        next_ = std::min(next_first_, next_second_);
    }

    static constexpr std::int64_t kBases[] = {1, 2, 5};  // base_evaluation_triggers "1,2,5"

    static std::int64_t first_value(std::int64_t exponent) {
        return static_cast<std::int64_t>(
            std::floor(std::pow(10.0, static_cast<double>(exponent) / kEvaluationsPerDecade)));
    }

    /// coco_observer_log_targets_trigger: true when `precision` reaches a new trigger.
    bool target_trigger(double precision) {
        if (std::isnan(precision)) return false;
        const double n = kTargetsPerDecade;
        if (precision >= 0) {
            const double verified = precision == 0 ? kPrecision / 10.0 : std::max(precision, kPrecision);
            const double e = std::ceil(std::log10(verified) * n);
            if (e < exponent_) {
                exponent_ = e;
                return true;
            }
            return false;
        }
        const double verified = precision > -kPrecision ? kPrecision : -precision;
        const double current = std::floor(std::log10(verified) * n);
        const double adjusted = 2 * std::ceil(std::log10(kPrecision / 10.0) * n) - current - 1;
        if (adjusted < exponent_) {
            exponent_ = adjusted;
            return true;
        }
        return false;
    }

    double reference_;
    std::int64_t dimension_;
    double exponent_ = INT_MAX;  // the last target trigger's exponent (COCO: an int from INT_MAX)
    std::int64_t next_first_ = 1, exponent1_ = 0;
    std::int64_t next_second_ = 0, exponent2_ = 0;
    std::int64_t next_ = 1;    // min(next_first_, next_second_): the next evaluation to check
    std::int64_t weight_ = 1;  // what an evaluation counts for the evaluation triggers
    std::size_t base_ = 0;
    std::vector<TracePoint> targets_, evaluations_;
};

}  // namespace pride
