#pragma once
// One run of a prepared campaign, as the store records it.
#include <cstdint>
#include <optional>
#include <string>

#include "experiment/campaign/campaign.hpp"
#include "experiment/storage/rows.hpp"

namespace pride::campaign {

/// One finished run, as the store keeps it.
using RunRecord = storage::RunRecord;

/// Runs one (problem, algorithm, seed) of a prepared campaign; the same inputs give the same
/// record (bar wall_ms), whatever thread or rank runs it.
RunRecord run_one(const CampaignProblem& p, const CampaignAlgorithm& a, const engine::Budget& budget,
                  std::int64_t seed);

/// The budget of one problem's runs: the campaign's, with its evaluations per dimension resolved.
engine::Budget problem_budget(const engine::Budget& budget, const CampaignProblem& p);

}  // namespace pride::campaign
