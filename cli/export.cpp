#include "cli/export.hpp"

#include <fmt/format.h>

#include <ostream>

#include "cli/output.hpp"
#include "engine/json.hpp"
#include "experiment/campaign/campaign.hpp"
#include "experiment/report/cec2017_import.hpp"
#include "experiment/report/coco_export.hpp"
#include "experiment/report/coco_import.hpp"
#include "experiment/report/ioh_export.hpp"
#include "experiment/report/ioh_import.hpp"
#include "framework/error.hpp"
#include "framework/output_files.hpp"

namespace pride::cli {

int export_command(const ExportOptions& o, std::ostream& out) {
    require(!o.ioh.empty() || !o.coco.empty(), "export", "name the folder to write: --ioh DIR or --coco DIR");
    OutputFiles files;
    if (!o.coco.empty()) {
        const report::CocoExportSummary c = report::export_coco(o.store, o.coco, files);
        std::string text = fmt::format("{} runs of {} algorithm{} written as COCO data ({} files) under {}\n", c.runs,
                                       c.algorithms, c.algorithms == 1 ? "" : "s", c.files, c.folder);
        if (c.skipped)
            text += fmt::format("{} run{} on problems outside the {} suite not written (not COCO's data)\n", c.skipped,
                                c.skipped == 1 ? "" : "s", c.suite);
        print_then_commit(out, text, files);
        return 0;
    }
    const report::ExportSummary written = report::export_ioh(o.store, o.ioh, files);
    print_then_commit(out, fmt::format("{} IOHprofiler files written under {}\n", written.files, written.folder),
                      files);
    return 0;
}

int import_command(const ImportOptions& o, std::ostream& out) {
    require(!o.coco.empty() || !o.cec2017.empty() || !o.ioh.empty(), "import",
            "name the data to read: --coco FOLDER (a COCO data set), --cec2017 FOLDER (a CEC 2017 entrant's files) "
            "or --ioh FOLDER (an algorithm's IOHprofiler files)");
    report::PublishedImportOptions options;
    options.name = o.name;
    options.citation = o.citation;
    const auto precisions = campaign::coco_precisions();
    const bool coco = !o.coco.empty(), ioh = !o.ioh.empty();
    const auto import = coco ? &report::import_coco : ioh ? &report::import_ioh : &report::import_cec2017;
    const std::string& folder = coco ? o.coco : ioh ? o.ioh : o.cec2017;
    const auto s = import(o.store, folder, options, precisions, engine::json_array(precisions));
    out << fmt::format("{} runs of published:{} imported into {} ({} problems of the store, {} added)\n", s.runs,
                       o.name, o.store, s.problems_matched, s.problems_added);
    return 0;
}

}  // namespace pride::cli
