#pragma once
// The HTML report's section of one problem (report_page.hpp): the convergence of each algorithm
// (median and quartiles over the seeds), boxplots of the final values and, on grids, each
// algorithm's best path on the map and the exact Pareto front of length and turns beside them; for
// a problem of several objectives, its hypervolume gaps and fronts (front_figures.hpp).
#include <string>
#include <vector>

#include "experiment/html/page_store.hpp"
#include "experiment/report/report.hpp"
#include "experiment/storage/reader.hpp"

namespace pride::html {

struct Page;

/// The legend's words for an algorithm's best path on the map: its value, seed and exact optimum,
/// and on a map with a world frame its length in cells and metres.
std::string best_path_label(const BestPath& b, const grid::GridMap& map);

/// The problem's heading, its figures (in a grid of two columns where the window is wide enough)
/// and their notes under them, added to `page`; `runs` are the problem's runs in the store `s`.
void problem_section(Page& page, const std::string& problem, const std::vector<const storage::StoredRun*>& runs,
                     const report::ReportData& r, const storage::CampaignStore& s, const PageStore& extra);

}  // namespace pride::html
