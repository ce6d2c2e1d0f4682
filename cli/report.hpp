#pragma once
// `pride report`: the comparison tables a paper needs, from a campaign store (campaign.hpp).
#include <iosfwd>
#include <string>

namespace pride::cli {

struct ReportOptions {
    std::string store;
    std::string format = "md";  // md, csv or latex
};
int report_command(const ReportOptions& o, std::ostream& out);

}  // namespace pride::cli
