#pragma once
// Campaigns as data: problems, algorithms, seeds and a budget, built from structs (the TOML file
// of `pride bench` is one front end: toml.hpp), prepared once (prepare.hpp) and run on a thread
// pool or over MPI ranks (run.hpp) into a store that commits finished runs as they come, so an
// interrupted campaign resumes with no run lost or run twice.
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/multiobjective.hpp"
#include "engine/run.hpp"
#include "engine/specs.hpp"

namespace pride::campaign {

struct CampaignProblem {
    std::string id;
    engine::ProblemSpec spec;  // ContinuousSpec or GridSpec; a grid's map may be left empty...
    std::string map_file;      // ... and named here (read once per (file, inflate) by prepare())
    std::int64_t inflate = 0;
    bool unknown_free = false;  // a map_server map's unknown cells read as free (grid::MapReadOptions)
    bool path_gaps = false;     // each run records its gaps to the shortest grid and any-angle lengths
    int line = 0;               // where it stands in the campaign file (0: not from a file)
    std::string suite;          // "bbob", "bbob-constrained", "classic", ... when it came from a suite, else empty
    // A grid's start or goal given as a world point in metres (start_world, goal_world): prepare()
    // puts the cell holding it into the spec once the map, and its frame, is read; `line` is the key's.
    struct WorldEnd {
        std::optional<grid::WorldPoint> point;
        int line = 0;
    };
    WorldEnd start_world, goal_world;
    std::shared_ptr<const engine::Problem> problem;  // built by prepare()
    // The evaluations of each run when the campaign budgets per dimension (set by prepare()).
    std::optional<std::int64_t> evaluations;
    std::string digest;  // problem_digest(), set by prepare()
    // A problem of several objectives (engine/multiobjective.hpp) when set: its objectives as the
    // campaign file gives them (a grid's criteria, "length,turns,clearance"; a catalog problem's M,
    // "3", or "" for the default), `spec` holding the rest (a ContinuousSpec naming zdt1..dtlz7
    // with its dim, 0 for the paper's; a GridSpec with the map, ends and encoding). prepare() puts
    // them into the spec it builds `problem` from (problem_spec()); each run stores its front and,
    // as its value, the hypervolume gap.
    std::optional<std::string> objectives;
    bool is_multiobjective() const { return objectives.has_value(); }
    /// The dimension of the box its algorithms search (once prepared).
    std::size_t dimension() const { return problem->dimension(); }
};

/// COCO's 51 target precisions: a continuous problem with a known optimum f_opt records in every
/// run the evaluations after which the best value first reached f_opt + 10^k, k = 2, 1.8, ...,
/// -8 (Hansen et al. 2022, "COCO: performance assessment", the runtime ECDFs' targets; cocopp's
/// 10**np.arange(2, -8.1, -0.2)).
inline const std::vector<double>& coco_precisions() {
    static const std::vector<double> p = [] {
        std::vector<double> v;
        for (int k = 0; k <= 50; ++k) v.push_back(std::pow(10.0, (10 - k) / 5.0));
        return v;
    }();
    return p;
}

struct CampaignAlgorithm {
    std::string id;
    engine::AlgorithmSpec spec;
    int line = 0;
};

struct Campaign {
    std::string file;  // for messages; empty when built in code
    std::string text;  // stored with the results, so a store never mixes two campaigns; empty:
                       // prepare() writes a canonical description
    std::string name;
    std::int64_t seeds = 0;  // runs per (problem, algorithm): seeds 1..seeds, or those of seed_list
    // The seeds when the file lists them (`seeds = [4, 5, 9]`, or a range): distinct, each in
    // [1, max_campaign_seeds], in the file's order, `seeds` their number; empty: 1..seeds. A run
    // is known by its seed's value, so seed 5 is one run whichever way the file gave it.
    std::vector<std::int64_t> seed_list;
    engine::Budget budget;  // evaluations and/or iterations
    // Where the file gives [budget]'s evaluations and iterations, and threads (0: not from a file),
    // for the messages that refuse them.
    int evaluations_line = 0, iterations_line = 0, threads_line = 0;
    // Or evaluations per dimension: each continuous problem's runs get this times its dimension
    // (COCO's budgets; excludes budget.evaluations; grids have no dimension and refuse it).
    std::optional<std::int64_t> evaluations_per_dim;
    std::optional<double> target;  // a threshold for reports (evaluations to reach it); runs do not stop there
    // The same as a precision: the threshold f_opt + precision of each problem with a known
    // optimum (the other problems have none). At most one of target and target_precision.
    std::optional<double> target_precision;
    // A published comparison's runs (experiment/campaign/protocol.hpp), or empty; its line in the file.
    std::string protocol;
    int protocol_line = 0;
    std::vector<CampaignProblem> problems;
    std::vector<CampaignAlgorithm> algorithms;
};

/// The k-th seed of the campaign (k from 0 to seeds - 1).
inline std::int64_t seed_at(const Campaign& c, std::int64_t k) {
    return c.seed_list.empty() ? k + 1 : c.seed_list[static_cast<std::size_t>(k)];
}

}  // namespace pride::campaign
