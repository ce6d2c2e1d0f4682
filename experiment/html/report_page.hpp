#pragma once
// A campaign's report as one self-contained page (`pride report STORE --html DIR`, Python's
// report(store, html=DIR)): DIR/index.html with its figures as SVG files beside it, nothing
// fetched from the network. The page holds the campaign's definition and provenance, the report's
// table and statistics (experiment/report/report.hpp), the ERT tables and runtime ECDFs
// (coco.hpp), and per problem the convergence of each algorithm, boxplots of the final values
// and, on grids, each algorithm's best path on the map and the exact Pareto front of length and
// turns beside them; for problems of several objectives, attainment surfaces, the median runs'
// fronts and their paths on grids (front_figures.hpp).
#include <cstddef>
#include <string>

#include "experiment/report/report.hpp"

namespace pride {
class OutputFiles;
}

namespace pride::html {

struct PageSummary {
    std::string index;        // DIR/index.html
    std::size_t figures = 0;  // SVG files beside it
};

/// Reads `store` whole, then writes the page. The folder is created (with its parents) or, when
/// it exists, added to (files of the same names replaced); every file is written to a temporary
/// name and all are renamed into place at the end, index.html last (framework/output_files.hpp),
/// so that a failure leaves no half-written report. Figures are named after problems by
/// storage::unique_file_names: ids such as "x/y" and "x_y" get files of their own. Errors are
/// InputError: the store's own (read_store), and InputError("html", ...) naming the folder or
/// file that cannot be written.
PageSummary write_report_page(const std::string& store, const std::string& dir,
                              const report::ReportOptions& options = {});
/// The same page, written to `files` and left for the caller to commit.
PageSummary write_report_page(const std::string& store, const std::string& dir, const report::ReportOptions& options,
                              OutputFiles& files);

}  // namespace pride::html
