#include "cli/export.hpp"

#include <fmt/format.h>

#include <ostream>

#include "experiment/report/ioh_export.hpp"
#include "framework/error.hpp"

namespace pride::cli {

int export_command(const ExportOptions& o, std::ostream& out) {
    require(!o.ioh.empty(), "--ioh", "name the folder to write");
    const report::ExportSummary written = report::export_ioh(o.store, o.ioh);
    out << fmt::format("{} IOHprofiler files written under {}\n", written.files, written.folder);
    return 0;
}

}  // namespace pride::cli
