#pragma once
// `pride report`: the comparison tables a paper needs, from a campaign store.
#include <iosfwd>
#include <string>
#include <vector>

namespace pride::cli {

struct ReportOptions {
    std::vector<std::string> stores;  // one, or several read as one (a campaign run in parts)
    std::string format = "md";        // md, csv, latex, ert-csv, functions-csv, cec or cec-csv
    std::string plots;                // a folder for the figures (python3-matplotlib), or empty
    std::string html;                 // a folder for the HTML page (experiment/html/), or empty
    bool raw = false;                 // values f rather than precisions f - f_opt
};
int report_command(const ReportOptions& o, std::ostream& out);

}  // namespace pride::cli
