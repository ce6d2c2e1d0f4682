#pragma once
// `pride export STORE --ioh DIR`: a campaign store as IOHprofiler files (the COCO-style `.info`
// and `.dat` files IOHanalyzer reads); `--coco DIR`: its bbob or bbob-constrained runs as COCO's
// own data files (cocopp). One folder per algorithm.
#include <iosfwd>
#include <string>

namespace pride::cli {

struct ExportOptions {
    std::string store;
    std::string ioh;   // the folder to write IOHprofiler files to
    std::string coco;  // or COCO's data files
};
int export_command(const ExportOptions& o, std::ostream& out);

}  // namespace pride::cli
