#pragma once
// The HTML report's figures of a problem of several objectives, from the fronts its
// runs stored: per algorithm the 25 %, 50 % and 75 % empirical attainment surfaces over its runs
// (two objectives; framework/pareto/attainment.hpp, Fonseca et al.), the front of its median run
// against the problem's reference front (the analytic front sampled, or a grid's exact front), and
// on grids the paths of that front on the map.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "engine/multiobjective.hpp"
#include "experiment/html/page_store.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/problem.hpp"

namespace pride::html {

struct Page;

/// The attainment surfaces drawn: the 25 %, 50 % and 75 % ones, the k-th of n runs for
/// k = ceil(q n).
inline constexpr std::array<double, 3> kAttainmentLevels{0.25, 0.5, 0.75};
std::size_t attainment_k(double q, std::size_t runs);

/// What the page draws of one algorithm on a problem of several objectives.
struct AlgorithmFronts {
    std::string algorithm;
    std::vector<const StoredFront*> runs;  // its runs whose fronts could be read, by seed
    // Two objectives: the surfaces of kAttainmentLevels, each the corners (2 x m) that
    // pareto::attainment_surface gives for k = attainment_k(q, runs); empty otherwise.
    std::vector<Matrix> surfaces;
    std::vector<std::size_t> k;
    // The run of median hypervolume ratio (runs ordered from the highest ratio, ties by seed; of
    // an even number, the better of the two middle ones).
    const StoredFront* median = nullptr;
};

struct ProblemFronts {
    std::vector<std::string> objectives;      // their names (those of most runs)
    std::vector<AlgorithmFronts> algorithms;  // by id
    std::vector<std::string> notes;           // runs left out, and why (plain text)
};

/// From the fronts `extra` holds of `problem` (pointers into it). Runs whose front could not be
/// read, or has other objectives than most runs, are left out, each named in a note.
ProblemFronts problem_fronts(const PageStore& extra, const std::string& problem);

/// The problem as the campaign ran it, rebuilt from what the store holds (its function and
/// dimension, or its grid's map, start, goal and corner cutting; `objectives` as its runs name
/// them), for its reference front. InputError saying why when it cannot be (a store from before
/// problems were stored, a map given in code or gone).
engine::Problem stored_problem(const storage::CampaignStore& s, const PageStore& extra, const std::string& problem,
                               const std::vector<std::string>& objectives);

/// Adds the figures of `problem` to the page, and notes under them for what cannot be drawn.
void front_figures(Page& page, const storage::CampaignStore& s, const PageStore& extra, const std::string& problem);

}  // namespace pride::html
