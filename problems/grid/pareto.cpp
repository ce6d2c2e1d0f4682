#include "problems/grid/pareto.hpp"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <limits>

#include "framework/error.hpp"
#include "framework/memory.hpp"
#include "problems/grid/objectives.hpp"

namespace pride::grid {

Criteria parse_criteria(std::string_view list) {
    Criteria c{false, false, false, false};
    require(!list.empty(), "objectives", "expected a list such as length,turns, got nothing");
    std::size_t begin = 0;
    while (begin <= list.size()) {
        const std::size_t comma = std::min(list.find(',', begin), list.size());
        const std::string_view name = list.substr(begin, comma - begin);
        bool* slot = nullptr;
        if (name == "length")
            slot = &c.length;
        else if (name == "turns")
            slot = &c.turns;
        else if (name == "angle" || name == "angle_penalty")
            slot = &c.angle_penalty;
        else if (name == "clearance")
            slot = &c.clearance;
        require(slot != nullptr, "objectives",
                "unknown objective '" + std::string(name) + "' (expected length, turns, angle or clearance)");
        require(!*slot, "objectives", "'" + std::string(name) + "' is given twice");
        *slot = true;
        begin = comma + 1;
    }
    require(c.count() >= 2, "objectives",
            "a Pareto front needs two to four objectives, got only '" + std::string(list) +
                "' (one objective's optimum: pride path --algo exact)");
    return c;
}

std::vector<std::string> criteria_names(const Criteria& c) {
    std::vector<std::string> names;
    if (c.length) names.emplace_back("length");
    if (c.turns) names.emplace_back("turns");
    if (c.angle_penalty) names.emplace_back("angle_penalty");
    if (c.clearance) names.emplace_back("clearance");
    return names;
}

namespace {

/// The sign of x - y sqrt(2) for integers x, y.
int sign_of(std::int64_t x, std::int64_t y) noexcept {
    if (x == 0 && y == 0) return 0;
    if (x >= 0 && y <= 0) return 1;
    if (x <= 0 && y >= 0) return -1;
    // Same signs: compare x^2 with 2 y^2 (never equal: sqrt(2) is irrational). The step counts of
    // a search stay below 2^26, so the squares fit easily.
    const std::int64_t xx = x * x, yy = 2 * y * y;
    return x > 0 ? (xx > yy ? 1 : -1) : (xx > yy ? -1 : 1);
}

}  // namespace

int compare_lengths(const StepCounts& x, const StepCounts& y) noexcept {
    const std::int64_t a = x.straight - y.straight, b = y.diagonal - x.diagonal;
    // Fast path: a - b sqrt(2) in doubles is off by less than 1e-8 while |b| < 2^26 (a is exact),
    // so a difference beyond 1e-6 has the sign it shows; closer ones are decided exactly.
    const double approx = static_cast<double>(a) - static_cast<double>(b) * kSqrt2;
    if (approx > 1e-6 && b < (std::int64_t{1} << 26) && -b < (std::int64_t{1} << 26)) return 1;
    if (approx < -1e-6 && b < (std::int64_t{1} << 26) && -b < (std::int64_t{1} << 26)) return -1;
    return sign_of(a, b);
}

namespace {

constexpr std::uint32_t kDirs = 9;  // 8 directions and "no step yet" (also: any, at the goal)
constexpr int kNone = 8;
constexpr std::uint32_t kNil = std::numeric_limits<std::uint32_t>::max();

// (A label's "dead" flag lives beside the labels, in a byte of its own: inside Label it would pad
// 28 bytes to 32.)
struct Label {
    std::int32_t straight, diagonal, turns, angle, clearance;
    std::uint32_t state, parent;
};

/// A label's costs as its state's list holds them, side by side for the dominance scans.
struct Costs {
    std::int32_t straight, diagonal, turns, angle, clearance;
    std::uint32_t label;
};

/// The open list's entry: the key (length + octile distance, exact; the other criteria in the
/// canonical order, 0 where unused) and the label.
struct Entry {
    std::int32_t straight, diagonal, k2, k3, k4;
    std::uint32_t label;
};

class Search {
  public:
    Search(const GridMap& map, const MapClearance& clearance, Cell s, Cell g, const Criteria& c, const ParetoOptions& o)
        : map_(map),
          clearance_(clearance),
          goal_(g),
          c_(c),
          o_(o),
          goal_index_(static_cast<std::uint32_t>(map.index(g))) {
        max_labels_ = std::min<std::size_t>(o.max_labels, std::size_t{1} << 25);
        lists_.resize(map.size() * kDirs);
        goal_state_ = goal_index_ * kDirs + kNone;
        if (c.clearance && o.use_heuristic) rest_clearance_ = least_clearance_to_goal();
        // Without turns and angle among the criteria no cost depends on the last direction, so a
        // cell is one state (on the bundled maps 2 to 5 times fewer labels for length and
        // clearance). Only for sets with clearance: the others keep their states, hence their paths.
        by_cell_ = c.clearance && !c.turns && !c.angle_penalty;
        // The criteria after length, in the canonical order, as the key's later parts.
        int parts = 0;
        if (c.turns) keys_[parts++] = &Label::turns;
        if (c.angle_penalty) keys_[parts++] = &Label::angle;
        if (c.clearance) keys_[parts++] = &Label::clearance;
        const auto start = static_cast<std::uint32_t>(map.index(s));
        insert({0, 0, 0, 0, clearance.cost(start), start * kDirs + kNone, kNil});
    }

    void run() {
        while (!heap_.empty()) {
            std::pop_heap(heap_.begin(), heap_.end(), later_);
            const std::uint32_t id = heap_.back().label;
            heap_.pop_back();
            if (dead_[id]) continue;
            const Label l = labels_[id];
            const std::uint32_t index = l.state / kDirs;
            const int last = by_cell_ ? last_step(l) : static_cast<int>(l.state % kDirs);
            if (o_.use_heuristic && bounded_by_goal(l, index, last)) continue;
            const int back = last == kNone ? -1 : (last + 4) % 8;  // a U-turn only makes a loop
            for (unsigned m = map_.moves(index, o_.corner_cutting); m != 0; m &= m - 1) {
                const int d = std::countr_zero(m);
                if (d == back) continue;
                const auto ni = static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(index) + map_.offset(d));
                Label next = l;
                next.state =
                    ni == goal_index_ ? goal_state_ : ni * kDirs + static_cast<std::uint32_t>(by_cell_ ? kNone : d);
                next.parent = id;
                (is_diagonal(d) ? next.diagonal : next.straight) += 1;
                if (last != kNone && last != d) {
                    next.turns += 1;
                    next.angle += angle_penalty_of_turn(turn_steps(last, d));
                }
                next.clearance += clearance_.cost(ni);
                insert(next);
            }
        }
    }

    std::vector<FrontPoint> front() const {
        std::vector<std::uint32_t> ids;
        for (const Costs& c : lists_[goal_state_]) ids.push_back(c.label);
        std::sort(ids.begin(), ids.end(), [&](std::uint32_t x, std::uint32_t y) {
            const Label &a = labels_[x], &b = labels_[y];
            const int c = compare_lengths({a.straight, a.diagonal}, {b.straight, b.diagonal});
            if (c != 0) return c < 0;
            if (a.turns != b.turns) return a.turns < b.turns;
            if (a.angle != b.angle) return a.angle < b.angle;
            if (a.clearance != b.clearance) return a.clearance < b.clearance;
            return x < y;
        });
        std::vector<FrontPoint> out;
        for (const std::uint32_t id : ids) {
            FrontPoint p;
            for (std::uint32_t i = id; i != kNil; i = labels_[i].parent)
                p.path.push_back(map_.cell(labels_[i].state / kDirs));
            std::reverse(p.path.begin(), p.path.end());
            const Label& l = labels_[id];
            p.steps = {l.straight, l.diagonal};
            p.length = metrics(p.path, false).length;
            p.turns = l.turns;
            p.angle_penalty = l.angle;
            p.clearance = l.clearance;
            out.push_back(std::move(p));
        }
        return out;
    }

    std::size_t labels() const noexcept { return labels_.size(); }

  private:
    /// x weakly dominates y in the chosen criteria, y's costs raised by (ds, dd, dt, da, dc).
    template <class X, class Y>
    bool dominates(const X& x, const Y& y, int ds = 0, int dd = 0, int dt = 0, int da = 0, int dc = 0) const noexcept {
        if (c_.turns && x.turns > y.turns + dt) return false;
        if (c_.angle_penalty && x.angle > y.angle + da) return false;
        if (c_.clearance && x.clearance > y.clearance + dc) return false;
        return !c_.length || compare_lengths({x.straight, x.diagonal}, {y.straight + ds, y.diagonal + dd}) <= 0;
    }

    /// The direction of a label's last step (kNone at the start), from its parent's cell: the turns
    /// and angle penalty its path reports when the states are cells.
    int last_step(const Label& l) const noexcept {
        if (l.parent == kNil) return kNone;
        return direction(map_.cell(labels_[l.parent].state / kDirs), map_.cell(l.state / kDirs));
    }

    /// The octile distance from cell `index` to the goal, as straight and diagonal steps.
    void octile(std::uint32_t index, int& straight, int& diagonal) const noexcept {
        const Cell c = map_.cell(index);
        const int dx = std::abs(c.x - goal_.x), dy = std::abs(c.y - goal_.y);
        diagonal = std::min(dx, dy);
        straight = std::max(dx, dy) - diagonal;
    }

    /// The least clearance still to pay from each cell to the goal (the cells entered after it, the
    /// goal's included): Dijkstra from the goal over the legal steps, which are symmetric (a step
    /// and its reverse need the same free cells). 0 where the goal cannot be reached (no bound).
    std::vector<std::int32_t> least_clearance_to_goal() const {
        constexpr std::int32_t kUnseen = -1;
        std::vector<std::int32_t> rest(map_.size(), kUnseen);
        using Item = std::pair<std::int32_t, std::uint32_t>;  // (rest, cell), smallest first
        std::vector<Item> open{{0, goal_index_}};
        const auto later = [](const Item& x, const Item& y) { return x.first > y.first; };
        while (!open.empty()) {
            std::pop_heap(open.begin(), open.end(), later);
            const auto [r, v] = open.back();
            open.pop_back();
            if (rest[v] != kUnseen) continue;
            rest[v] = r;
            const std::int32_t through = r + clearance_.cost(v);  // a neighbour's rest through v
            for (unsigned m = map_.moves(v, o_.corner_cutting); m != 0; m &= m - 1) {
                const auto u =
                    static_cast<std::uint32_t>(static_cast<std::ptrdiff_t>(v) + map_.offset(std::countr_zero(m)));
                if (rest[u] == kUnseen) {
                    open.push_back({through, u});
                    std::push_heap(open.begin(), open.end(), later);
                }
            }
        }
        for (auto& r : rest) r = std::max(r, 0);
        return rest;
    }

    /// A label at (index, last) whose every completion is weakly dominated by a goal label: its
    /// costs plus lower bounds of the rest (the octile distance; a turn of at least 45 degrees
    /// when the goal is not straight ahead; the least clearance from its cell to the goal) are.
    bool bounded_by_goal(const Label& l, std::uint32_t index, int last) const noexcept {
        if (index == goal_index_) return false;  // the goal list itself decides
        int hs = 0, hd = 0;
        octile(index, hs, hd);
        int ht = 0;
        if (last != kNone) {
            const Cell c = map_.cell(index);
            const int dx = goal_.x - c.x, dy = goal_.y - c.y;
            const int t = std::max(std::abs(dx), std::abs(dy));
            ht = dx == t * kDx[last] && dy == t * kDy[last] ? 0 : 1;
        }
        const std::int32_t hc = rest_clearance_.empty() ? 0 : rest_clearance_[index];
        for (const Costs& c : lists_[goal_state_])
            if (dominates(c, l, hs, hd, ht, 10 * ht, hc)) return true;
        return false;
    }

    void insert(const Label& candidate) {
        const std::uint32_t index = candidate.state / kDirs;
        if (o_.use_heuristic && bounded_by_goal(candidate, index, static_cast<int>(candidate.state % kDirs))) return;
        // The state's list: stop at a label that dominates the candidate, kill (and drop) those it
        // dominates. The order of a list does not matter: an equal vector is never added twice.
        std::vector<Costs>& list = lists_[candidate.state];
        std::size_t kept = 0;
        for (std::size_t k = 0; k < list.size(); ++k) {
            // Once the candidate dominates a label, no other one dominates the candidate (it would
            // dominate that label too, and a list holds no dominated label).
            if (kept == k && dominates(list[k], candidate)) return;
            if (dominates(candidate, list[k])) {
                dead_[list[k].label] = 1;
                continue;
            }
            list[kept++] = list[k];
        }
        list.resize(kept);
        if (labels_.size() >= max_labels_)  // (not require(): its message would be built every time)
            throw InputError("pareto",
                             "the front needs more than " + std::to_string(max_labels_) + " labels on " + map_.name());
        const auto id = static_cast<std::uint32_t>(labels_.size());
        labels_.push_back(candidate);
        dead_.push_back(0);
        list.push_back(
            {candidate.straight, candidate.diagonal, candidate.turns, candidate.angle, candidate.clearance, id});
        if (candidate.state == goal_state_) return;  // goal labels are not extended
        int hs = 0, hd = 0;
        if (o_.use_heuristic) octile(index, hs, hd);
        heap_.push_back({candidate.straight + hs, candidate.diagonal + hd, keys_[0] ? candidate.*keys_[0] : 0,
                         keys_[1] ? candidate.*keys_[1] : 0, keys_[2] ? candidate.*keys_[2] : 0, id});
        std::push_heap(heap_.begin(), heap_.end(), later_);
    }

    struct Later {
        bool length;
        /// The heap's order: the smallest key first, then the label created first.
        bool operator()(const Entry& x, const Entry& y) const noexcept {
            if (length)
                if (const int c = compare_lengths({x.straight, x.diagonal}, {y.straight, y.diagonal}); c != 0)
                    return c > 0;
            if (x.k2 != y.k2) return x.k2 > y.k2;
            if (x.k3 != y.k3) return x.k3 > y.k3;
            if (x.k4 != y.k4) return x.k4 > y.k4;
            return x.label > y.label;
        }
    };

    const GridMap& map_;             // (the search lives inside one front() call)
    const MapClearance& clearance_;  // (likewise)
    Cell goal_;
    Criteria c_;
    ParetoOptions o_;
    std::uint32_t goal_index_, goal_state_ = 0;
    std::vector<std::int32_t> rest_clearance_;  // per cell, when clearance is a criterion and bounds are on
    std::size_t max_labels_ = 0;
    std::int32_t Label::*keys_[3] = {nullptr, nullptr, nullptr};
    bool by_cell_ = false;  // states are cells, not (cell, last direction)
    Later later_{c_.length};
    std::vector<std::vector<Costs>> lists_;  // per state: the costs of its live labels
    std::vector<Label> labels_;
    std::vector<std::uint8_t> dead_;  // per label: dominated since it was created
    std::vector<Entry> heap_;
};

void check_inputs(const GridMap& map, const Criteria& criteria) {
    require(criteria.count() >= 1, "objectives", "at least one of length, turns, angle and clearance is needed");
    // Every label's costs stay below 63 * 2^25 < 2^31 (a step adds at most 50 of angle penalty and
    // 63 of clearance), states are indexed by 32 bits, and the per-state lists take 24 bytes per
    // state before any label exists (216 MB at the limit).
    require(map.size() <= 1'000'000, "map",
            map.name() + " has " + std::to_string(map.size()) + " cells; the Pareto front takes at most 1000000");
}

}  // namespace

std::vector<FrontPoint> ParetoSearch::front(const GridMap& map, Cell s, Cell g, const Criteria& criteria,
                                            const ParetoOptions& options) {
    labels_ = 0;
    check_inputs(map, criteria);  // before the clearance is allocated
    return front(map, MapClearance(map), s, g, criteria, options);
}

std::vector<FrontPoint> ParetoSearch::front(const GridMap& map, const MapClearance& clearance, Cell s, Cell g,
                                            const Criteria& criteria, const ParetoOptions& options) {
    labels_ = 0;
    check_inputs(map, criteria);
    require(clearance.width() == map.width() && clearance.height() == map.height(), "clearance",
            "computed for a " + std::to_string(clearance.width()) + "x" + std::to_string(clearance.height()) +
                " map, not for the " + std::to_string(map.width()) + "x" + std::to_string(map.height()) + " map " +
                map.name());
    if (!map.free(s) || !map.free(g)) return {};
    if (s == g) return {FrontPoint{{0, 0}, 0.0, 0, 0, clearance.cost(s), Path{s}}};
    Search search(map, clearance, s, g, criteria, options);
    search.run();
    labels_ = search.labels();
    return search.front();
}

std::optional<double> iqga_optimum(const GridMap& map, Cell s, Cell g, bool corner_cutting, Path* out) {
    ParetoOptions o;
    o.corner_cutting = corner_cutting;
    const auto front = pareto_front(map, s, g, Criteria{true, true, true}, o);
    std::optional<double> best;
    const FrontPoint* at = nullptr;
    for (const auto& p : front) {
        const double v = IqgaObjective{}(metrics(p.path));
        if (!best || v < *best) {
            best = v;
            at = &p;
        }
    }
    if (out && at) *out = at->path;
    return best;
}

std::size_t label_limit(std::size_t cells, double memory, const std::string& map_name) {
    const double lists = 24.0 * 9.0 * static_cast<double>(cells);
    require(lists < 0.5 * memory, "map",
            "the Pareto front on " + map_name + " needs " + format_bytes(lists) +
                " before its first label; this machine has " + format_bytes(memory));
    return static_cast<std::size_t>(std::max(1.0, (0.8 * memory - lists) / 77.0));
}

}  // namespace pride::grid
