#pragma once
// What identifies a campaign and its runs in a store: canonical texts of its budget, problems and
// algorithms, and the digests of its prepared problems.
#include <cstddef>
#include <string>

#include "experiment/campaign/campaign.hpp"
#include "experiment/storage/rows.hpp"
#include "problems/grid/map.hpp"

namespace pride::campaign {

/// A canonical text of a campaign built in code (prepare() stores it when the campaign has no file
/// text), so that a store is never mixed with another's.
std::string campaign_text(const Campaign& c);

/// What identifies a campaign's runs beside their seeds (a campaign grows by seeds, problems and
/// algorithms; these must not change under a stored id): its budget, each problem's definition
/// (function, dimension and instance, or map, ends and grid settings) and each algorithm's
/// (registered name and parameters), as canonical one-line texts.
std::string budget_definition(const Campaign& c);
std::string problem_definition(const CampaignProblem& p);
std::string algorithm_definition(const CampaignAlgorithm& a);

/// What a store records of a prepared problem beside its definition, so that a resume or a merge
/// on another problem under the same id is refused: "map sha256:HEX; settings sha256:HEX" for a
/// grid (the map's size and cells as the runs see them, inflated; not its path, so a map moved
/// or given in code is the same map), "settings sha256:HEX" otherwise. The settings are every
/// field that defines the problem: a grid's start, goal, objective, weights, lambda, inflate,
/// corner cutting, encoding, connector, init and waypoints; a function's name, dimension and
/// instance; a Python function's id, bounds and f_opt. Python code (a function, a path objective,
/// a step cost) cannot be identified: only that there is one.
std::string problem_digest(const CampaignProblem& p);

/// A name as a store keeps it (the campaign's name, problem and algorithm ids): an empty one, a
/// NUL (SQLite would cut the name there) or another control character (printed raw on a
/// terminal) gives what is wrong, else an empty string.
inline constexpr std::size_t kMaxNameBytes = 100;
std::string name_problem(const std::string& name);

/// The parts of problem_digest, for a prepare() that hashes each map once: the digest of a map's
/// size and cells, and the whole digest from it (empty for a problem without a map).
std::string map_digest(const grid::GridMap& m);
std::string compose_digest(const std::string& map_hex, const CampaignProblem& p);

/// The campaign as a store records it: its rows, with every definition and digest (a prepared
/// campaign: its problems built and digested).
storage::CampaignRows store_rows(const Campaign& c);

}  // namespace pride::campaign
