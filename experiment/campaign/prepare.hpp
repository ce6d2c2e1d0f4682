#pragma once
// A campaign made ready to run: its suites' rules applied, every id and parameter checked, every
// problem built once and its memory counted, before any run starts.
#include <cstddef>
#include <cstdint>
#include <string>

#include "experiment/campaign/campaign.hpp"

namespace pride::campaign {

/// The spec a problem is built from: its campaign entry's, with the objectives of a problem of
/// several (CampaignProblem::objectives) put into it (the map of a grid as loaded).
engine::ProblemSpec problem_spec(const CampaignProblem& p);

/// At most this many problems in one campaign (COCO's largest suites have a few thousand): a short
/// instance list or suite must not start hours of building (each problem takes about 12 kB and
/// 80 us to build before its rotation: a 6.9 MB file asked for a million).
inline constexpr std::size_t max_campaign_problems = 100'000;

/// At most this many seeds per problem and algorithm, in a campaign file (`seeds`), in Python's
/// Campaign and in a campaign built in code (prepare() checks it for all): one limit, stated here.
inline constexpr std::int64_t max_campaign_seeds = 1'000'000;

/// The words a `seeds` beyond [1, max_campaign_seeds] is refused with.
inline std::string seeds_range_message(std::int64_t seeds) {
    return "must be in [1, " + std::to_string(max_campaign_seeds) + "], got " + std::to_string(seeds);
}

/// The memory a problem takes once prepare() has built it, estimated from its spec before any of
/// it is: a built problem's tables (about 11 kB measured; 16 kB counted with its CampaignProblem
/// and id), a continuous instance's vectors and rotation (8 dim and 2 dim^2 doubles); a grid's
/// map is counted once per file by load_map.
double problem_memory(const engine::ProblemSpec& spec);

/// Whether every algorithm of the campaign plans on the whole map (A*, JPS, Theta*, OMPL's
/// planners, ...): then it needs no budget, and refuses one none of them would use (prepare()).
bool planners_only(const Campaign& c);

/// The memory one run of a campaign takes in the lists made before any starts (its task, its key
/// with both ids, its place in the set of stored keys), for ids of these lengths.
double run_list_memory(std::size_t problem_id_length, std::size_t algorithm_id_length);

/// The CEC suites' rules where the campaign leaves them open (docs/campaigns.md, "The CEC
/// suites"; prepare() applies them first, data-free): without an evaluation budget (evaluations
/// or evaluations_per_dim), each problem of a CEC suite (cec2017-fN, cec2022-fN, from a [[suite]]
/// or a [[problem]]) runs its suite's MaxFES (CampaignProblem::evaluations; with iterations too,
/// whichever ends first), and a campaign without any budget must hold CEC problems only; without
/// seeds (0), a campaign of one CEC suite's problems runs the competition's number of runs (51
/// for cec2017, 30 for cec2022, seeds 1..N), any other is refused. InputError naming the file.
void apply_suite_rules(Campaign& campaign);

/// Checks the campaign and builds every problem once (each map read once): a missing or duplicate
/// id, a bad problem, an unknown algorithm, a bad parameter, an algorithm that cannot run on a
/// problem, or a run that would not fit in memory is an InputError naming the file and line (or
/// the id), so a campaign that starts will not fail half-way on its input.
void prepare(Campaign& campaign);

}  // namespace pride::campaign
