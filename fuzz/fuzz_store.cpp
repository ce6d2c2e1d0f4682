// Campaign stores as `pride report` and `pride export --ioh` read them (experiment/report): the input
// bytes are the SQLite file, so tampered, truncated and foreign databases all come through here.
// Each is loaded and checked (report::load_report), rendered in every format the report has, and
// exported to IOHprofiler files in the scratch folder.
#include <filesystem>

#include "experiment/report/ioh_export.hpp"
#include "experiment/report/report.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace pride;
    const std::string path = fuzz::write_input(fuzz::text(data, size), "store.sqlite");
    std::error_code ec;
    std::filesystem::remove(path + "-journal", ec);
    std::filesystem::remove(path + "-wal", ec);
    std::filesystem::remove(path + "-shm", ec);
    try {
        const report::ReportData r = report::load_report(path);
        (void)report::render_markdown(r);
        (void)report::render_csv(r);
        (void)report::render_latex(r);
        if (r.coco) (void)report::render_ert_csv(r);
    } catch (const InputError&) {
    }
    const auto folder = fuzz::scratch() / "ioh";
    try {
        (void)report::export_ioh(path, folder.string());
    } catch (const InputError&) {
    }
    std::filesystem::remove_all(folder, ec);
    return 0;
}
