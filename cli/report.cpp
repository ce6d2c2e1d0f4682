#include "cli/report.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "experiment/html/report_page.hpp"
#include "experiment/report/report.hpp"
#include "framework/error.hpp"

namespace pride::cli {
namespace {

/// `text` as one word for /bin/sh.
std::string shell_quote(const std::string& text) {
    std::string s = "'";
    for (const char c : text) s += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return s + "'";
}

/// Runs scripts/plot_campaign.py with Debian's python3 (the one python3-matplotlib serves), and
/// with the campaign's precisions scripts/plot_ecdf.py on the ECDF curves computed here
/// (experiment/report/coco.hpp), written to DIR/ecdf.json, so the plots and the tables share one
/// definition.
/// Runs `python script args...`, its standard error kept aside: nothing of it is shown on
/// success (library warnings), its last line on failure (the scripts print one line).
void run_script(const std::string& python, const std::string& script, const std::vector<std::string>& args,
                const std::string& folder) {
    const std::string errors = (std::filesystem::path(folder) / ".plot-errors.txt").string();
    std::string command = "PYTHONWARNINGS=ignore MPLBACKEND=Agg '" + python + "' '" + script + "'";
    for (const auto& a : args) command += " " + shell_quote(a);
    command += " 2>" + shell_quote(errors);
    const int status = std::system(command.c_str());
    std::string last;
    {
        std::ifstream f(errors);
        for (std::string line; std::getline(f, line);)
            if (!line.empty()) last = line;
    }
    std::error_code ec;
    std::filesystem::remove(errors, ec);
    if (status != 0) {
        const std::string name = std::filesystem::path(script).filename().string();
        if (last.empty()) throw InputError("--plots", name + " failed");
        throw InputError(last.rfind(name, 0) == 0 ? "--plots: " + last : last);
    }
}

/// Runs scripts/plot_campaign.py with Debian's python3 (the one python3-matplotlib serves), and
/// with the campaign's precisions scripts/plot_ecdf.py on the ECDF curves computed here
/// (experiment/report/coco.hpp), written to DIR/ecdf.json, so the plots and the tables share one
/// definition.
void plot(const std::string& store, const std::string& folder, const report::ReportData& data) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    require(!ec && std::filesystem::is_directory(folder), "--plots", folder + ": cannot create the folder");
    const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    const std::string script = std::string(PRIDE_SCRIPTS_DIR) + "/plot_campaign.py";
    require(std::filesystem::exists(script), "--plots", script + " is missing");
    const std::string check = "'" + python + "' -c 'import matplotlib' >/dev/null 2>&1";
    require(std::system(check.c_str()) == 0, "--plots",
            "needs python3 with matplotlib (apt-get install python3-matplotlib)");
    std::vector<std::string> args{store, folder};
    if (data.raw) args.push_back("--raw");
    run_script(python, script, args, folder);
    if (!data.coco || data.coco->curves.empty()) return;
    const std::string ecdf_script = std::string(PRIDE_SCRIPTS_DIR) + "/plot_ecdf.py";
    require(std::filesystem::exists(ecdf_script), "--plots", ecdf_script + " is missing");
    const std::string json = (std::filesystem::path(folder) / "ecdf.json").string();
    {
        std::ofstream f(json);
        f << report::coco::ecdf_json(data.campaign, *data.coco);
        f.close();
        require(!f.fail(), "--plots", json + ": cannot write the file");
    }
    run_script(python, ecdf_script, {json, folder}, folder);
}

}  // namespace

int report_command(const ReportOptions& o, std::ostream& out) {
    require(o.format == "md" || o.format == "csv" || o.format == "latex" || o.format == "ert-csv", "--format",
            "expected md, csv, latex or ert-csv, got '" + o.format + "'");
    if (!o.html.empty()) {
        // The page holds the tables itself; what is printed is where it is.
        require(o.format == "md", "--format", o.format + " is printed without --html; --html writes the page alone");
        require(o.stores.size() == 1, "--html", "draws one store; join several into one with pride merge first");
        require(o.plots.empty(), "--plots", "give --plots or --html, not both (the page has its own figures)");
        const html::PageSummary page = html::write_report_page(o.stores.front(), o.html, report::ReportOptions{o.raw});
        out << page.index << ": the report, with " << page.figures << " figures\n";
        return 0;
    }
    // The whole store is read and checked before any figure is drawn from it.
    require(o.plots.empty() || o.stores.size() == 1, "--plots",
            "draws one store; join several into one with pride merge first");
    const report::ReportData data = report::load_report(o.stores, report::ReportOptions{o.raw});
    require(o.format != "ert-csv" || data.coco, "--format ert-csv",
            o.stores.front() + ": records no target hits (no precisions, or no run on a problem with a known optimum)");
    const std::string text = o.format == "csv"       ? report::render_csv(data)
                             : o.format == "ert-csv" ? report::render_ert_csv(data)
                             : o.format == "md"      ? report::render_markdown(data)
                                                     : report::render_latex(data);
    if (!o.plots.empty()) plot(o.stores.front(), o.plots, data);
    out << text;
    return 0;
}

}  // namespace pride::cli
