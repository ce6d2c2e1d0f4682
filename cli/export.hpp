#pragma once
// `pride export STORE --ioh DIR`: a campaign store as IOHprofiler files (the COCO-style `.info`
// and `.dat` files IOHanalyzer reads), one folder per algorithm.
#include <iosfwd>
#include <string>

namespace pride::cli {

struct ExportOptions {
    std::string store;
    std::string ioh;  // the folder to write
};
int export_command(const ExportOptions& o, std::ostream& out);

}  // namespace pride::cli
