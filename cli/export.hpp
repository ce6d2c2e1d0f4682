#pragma once
// `pride export STORE --ioh DIR`: a campaign store as IOHprofiler files (the COCO-style `.info`
// and `.dat` files IOHanalyzer reads); `--coco DIR`: its bbob or bbob-constrained runs as COCO's
// own data files (cocopp). One folder per algorithm. `pride import` reads such a folder back as
// published runs.
#include <iosfwd>
#include <string>

namespace pride::cli {

struct ExportOptions {
    std::string store;
    std::string ioh;   // the folder to write IOHprofiler files to
    std::string coco;  // or COCO's data files
};
int export_command(const ExportOptions& o, std::ostream& out);

/// `pride import STORE --coco FOLDER --name NAME --citation TEXT`: a COCO bbob data set's runs
/// added to the store as the published algorithm "published:NAME" (experiment/report/coco_import.hpp);
/// `--cec2017 FOLDER`: one CEC 2017 entrant's result files (experiment/report/cec2017_import.hpp);
/// `--ioh FOLDER`: one algorithm's IOHprofiler files, as `pride export --ioh` writes them, onto the
/// store's own problems (experiment/report/ioh_import.hpp).
struct ImportOptions {
    std::string store;
    std::string coco;     // the data set's folder (a .tgz extracted)
    std::string cec2017;  // or the entrant's folder of NAME_F_D.txt files
    std::string ioh;      // or an algorithm's folder of IOHprofiler .info and .dat files
    std::string name, citation;
};
int import_command(const ImportOptions& o, std::ostream& out);

}  // namespace pride::cli
