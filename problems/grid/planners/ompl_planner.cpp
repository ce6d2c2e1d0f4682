// OMPL's planners on the grid's plane (ompl_planner.hpp): validity from pride's exact point and
// segment tests, a budget in checks enforced inside the checkers, reproducible seeding.
#include "problems/grid/planners/ompl_planner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "framework/error.hpp"

namespace pride::grid {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

Point point_of(const ob::State* s) {
    const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
    return {v->values[0], v->values[1]};
}

/// The checks made, shared by the two checkers. Atomic because OMPL may test the termination
/// condition from another thread than the one checking.
struct Budget {
    std::int64_t max_checks = 0;
    std::atomic<std::int64_t> states{0}, motions{0};
    std::atomic<bool> lifted{false};  // for the simplifier under a time budget alone

    bool spent() const noexcept { return max_checks > 0 && states + motions >= max_checks; }
    /// Counts one check of that kind, or refuses it when the budget is spent.
    bool take(std::atomic<std::int64_t>& kind) noexcept {
        if (!lifted && spent()) return false;
        ++kind;
        return true;
    }
};

class PointChecker : public ob::StateValidityChecker {
  public:
    PointChecker(const ob::SpaceInformationPtr& si, const GridMap& map, Budget& budget)
        : ob::StateValidityChecker(si), map_(map), budget_(budget) {}
    bool isValid(const ob::State* s) const override {
        return budget_.take(budget_.states) && point_is_free(map_, point_of(s));
    }

  private:
    const GridMap& map_;
    Budget& budget_;
};

class SegmentValidator : public ob::MotionValidator {
  public:
    SegmentValidator(const ob::SpaceInformationPtr& si, const GridMap& map, Budget& budget)
        : ob::MotionValidator(si), map_(map), budget_(budget) {}

    bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
        const bool ok = budget_.take(budget_.motions) && segment_is_free(map_, point_of(s1), point_of(s2));
        ok ? ++valid_ : ++invalid_;
        return ok;
    }

    /// The last valid point by bisection on the segment's prefixes (a prefix of a free segment is
    /// free): conservative, within 2^-30 of the segment's length. One check for the budget.
    bool checkMotion(const ob::State* s1, const ob::State* s2, std::pair<ob::State*, double>& last) const override {
        if (!budget_.take(budget_.motions)) {
            last.second = 0.0;
            if (last.first) si_->copyState(last.first, s1);
            ++invalid_;
            return false;
        }
        const Point a = point_of(s1), b = point_of(s2);
        if (segment_is_free(map_, a, b)) {
            ++valid_;
            return true;
        }
        const auto at = [&](double t) { return Point{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; };
        double lo = 0.0, hi = 1.0;
        for (int i = 0; i < 30; ++i) {
            const double mid = 0.5 * (lo + hi);
            (segment_is_free(map_, a, at(mid)) ? lo : hi) = mid;
        }
        last.second = lo;
        if (last.first) si_->getStateSpace()->interpolate(s1, s2, lo, last.first);
        ++invalid_;
        return false;
    }

  private:
    const GridMap& map_;
    Budget& budget_;
};

/// PRM* grown by pride, not by PRM::solve (see ompl_planner.hpp): one thread, no wall-clock
/// phases. `on_connected` is called once, when start and goal first share a component.
class GrownPRMstar : public og::PRMstar {
  public:
    GrownPRMstar(const ob::SpaceInformationPtr& si, std::function<void()> on_connected)
        : og::PRMstar(si), on_connected_(std::move(on_connected)) {}

    ob::PlannerStatus solve(const ob::PlannerTerminationCondition& ptc) override {
        checkValidity();
        while (const ob::State* s = pis_.nextStart()) startM_.push_back(addMilestone(si_->cloneState(s)));
        if (startM_.empty()) return ob::PlannerStatus::INVALID_START;
        if (goalM_.empty())
            if (const ob::State* g = pis_.nextGoal(ptc)) goalM_.push_back(addMilestone(si_->cloneState(g)));
        if (goalM_.empty()) return ob::PlannerStatus::INVALID_GOAL;
        bool connected = false;
        const auto poll = [&] {
            if (!connected && sameComponent(startM_.front(), goalM_.front())) {
                connected = true;
                on_connected_();
            }
        };
        poll();  // the goal may have joined the start's component when it was added
        growRoadmap(ob::PlannerTerminationCondition([&] {
            poll();
            return ptc();
        }));
        poll();
        if (!connected) return ob::PlannerStatus::TIMEOUT;
        const ob::PathPtr path = constructSolution(startM_.front(), goalM_.front());
        if (!path) return ob::PlannerStatus::TIMEOUT;
        pdef_->addSolutionPath(path, false, 0.0, getName());
        return ob::PlannerStatus::EXACT_SOLUTION;
    }

  private:
    std::function<void()> on_connected_;
};

/// OMPL's log level for the scope, restored after.
class QuietOmpl {
  public:
    QuietOmpl() : saved_(ompl::msg::getLogLevel()) { ompl::msg::setLogLevel(ompl::msg::LOG_NONE); }
    ~QuietOmpl() { ompl::msg::setLogLevel(saved_); }
    QuietOmpl(const QuietOmpl&) = delete;
    QuietOmpl& operator=(const QuietOmpl&) = delete;

  private:
    ompl::msg::LogLevel saved_;
};

/// One run at a time: OMPL's seed generator and log level are process-wide.
std::mutex& run_mutex() {
    static std::mutex m;
    return m;
}

std::string cell_text(Cell c) {
    return "(" + std::to_string(c.x) + "," + std::to_string(c.y) + ")";
}

}  // namespace

const std::vector<std::string>& ompl_planner_names() {
    static const std::vector<std::string> names{"RRTstar", "InformedRRTstar", "BITstar", "PRMstar"};
    return names;
}

OmplOutcome plan_with_ompl(const GridMap& map, Cell start, Cell goal, const OmplRequest& request) {
    const auto& names = ompl_planner_names();
    if (std::find(names.begin(), names.end(), request.planner) == names.end()) {
        std::string known;
        for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
        throw InputError("planner", "unknown OMPL planner '" + request.planner + "' (known: " + known + ")");
    }
    require(std::isfinite(request.time_limit_s) && request.time_limit_s >= 0.0, "time_limit_s",
            "must be a number of seconds >= 0, got " + std::to_string(request.time_limit_s));
    require(request.max_checks >= 0, "max_checks", "must be >= 0, got " + std::to_string(request.max_checks));
    require(request.time_limit_s > 0.0 || request.max_checks > 0, "max_checks",
            "a budget is needed: max_checks > 0 or time_limit_s > 0 (the planners run until it ends)");
    require(map.free(start), "start", cell_text(start) + " is blocked or outside");
    require(map.free(goal), "goal", cell_text(goal) + " is blocked or outside");

    OmplOutcome out;
    if (start == goal) {
        out.solved = true;
        out.polyline = {centre_point(start)};
        out.first_solution_ms = 0.0;
        return out;
    }

    std::lock_guard<std::mutex> lock(run_mutex());
    QuietOmpl quiet;
    // OMPL's RNGs draw their seeds from one process-wide generator; reseeding it before anything is
    // built makes the run's RNGs the same for the same seed. OMPL takes a non-zero 32-bit seed
    // (its generator reduces it modulo 2147483563 anyway).
    ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(request.seed % 2147483562u) + 1u);

    Budget budget;
    // With simplify, a tenth of a check budget is kept for the simplifier, so that planning and
    // simplifying together stay within it.
    budget.max_checks =
        request.simplify && request.max_checks > 0 ? request.max_checks - request.max_checks / 10 : request.max_checks;

    auto space = std::make_shared<ob::RealVectorStateSpace>(2);
    ob::RealVectorBounds bounds(2);
    bounds.setLow(0, 0.0);
    bounds.setHigh(0, map.width());
    bounds.setLow(1, 0.0);
    bounds.setHigh(1, map.height());
    space->setBounds(bounds);
    auto si = std::make_shared<ob::SpaceInformation>(space);
    si->setStateValidityChecker(std::make_shared<PointChecker>(si, map, budget));
    si->setMotionValidator(std::make_shared<SegmentValidator>(si, map, budget));
    si->setup();

    ob::ScopedState<ob::RealVectorStateSpace> s(space), g(space);
    const Point ps = centre_point(start), pg = centre_point(goal);
    s[0] = ps.x;
    s[1] = ps.y;
    g[0] = pg.x;
    g[1] = pg.y;
    auto pdef = std::make_shared<ob::ProblemDefinition>(si);
    pdef->setStartAndGoalStates(s, g);
    pdef->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));

    const Clock::time_point t0 = Clock::now();
    const auto first_solution = [&] {
        if (out.first_solution_ms < 0.0) out.first_solution_ms = ms_since(t0);
    };
    pdef->setIntermediateSolutionCallback(
        [&](const ob::Planner*, const std::vector<const ob::State*>&, const ob::Cost&) { first_solution(); });

    ob::PlannerPtr planner;
    if (request.planner == "RRTstar")
        planner = std::make_shared<og::RRTstar>(si);
    else if (request.planner == "InformedRRTstar")
        planner = std::make_shared<og::InformedRRTstar>(si);
    else if (request.planner == "BITstar")
        planner = std::make_shared<og::BITstar>(si);
    else
        planner = std::make_shared<GrownPRMstar>(si, first_solution);
    planner->setProblemDefinition(pdef);
    planner->setup();

    const double limit_ms = 1000.0 * request.time_limit_s;
    const ob::PlannerTerminationCondition ptc(
        [&] { return budget.spent() || (limit_ms > 0.0 && ms_since(t0) >= limit_ms); });
    planner->solve(ptc);
    out.planning_ms = ms_since(t0);
    out.state_checks = budget.states;
    out.motion_checks = budget.motions;

    if (!pdef->hasExactSolution()) return out;
    auto path = std::dynamic_pointer_cast<og::PathGeometric>(pdef->getSolutionPath());
    if (!path || path->getStateCount() < 2) return out;
    if (request.simplify) {
        if (request.max_checks > 0)
            budget.max_checks = request.max_checks;  // the kept tenth; a refused check only keeps a segment
        else
            budget.lifted = true;
        const std::int64_t before = budget.states + budget.motions;
        og::PathSimplifier(si).simplifyMax(*path);
        out.simplify_checks = budget.states + budget.motions - before;
    }
    for (std::size_t i = 0; i < path->getStateCount(); ++i) out.polyline.push_back(point_of(path->getState(i)));
    // The goal is a GoalState sampled exactly; anything else would be OMPL's approximation.
    if (!(out.polyline.front() == ps) || !(out.polyline.back() == pg)) {
        out.polyline.clear();
        return out;
    }
    for (std::size_t i = 1; i < out.polyline.size(); ++i)
        if (!segment_is_free(map, out.polyline[i - 1], out.polyline[i]))
            throw std::logic_error("plan_with_ompl: " + request.planner + " returned a blocked segment");
    out.solved = true;
    return out;
}

}  // namespace pride::grid
