#include "cli/export.hpp"

#include <fmt/format.h>

#include <ostream>

#include "cli/output.hpp"
#include "experiment/report/coco_export.hpp"
#include "experiment/report/ioh_export.hpp"
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

}  // namespace pride::cli
