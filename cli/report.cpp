#include "cli/report.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "cli/numbers.hpp"
#include "cli/output.hpp"
#include "engine/specs.hpp"
#include "experiment/html/page_store.hpp"
#include "experiment/html/report_page.hpp"
#include "experiment/report/cec.hpp"
#include "experiment/report/cec2020rw_table.hpp"
#include "experiment/report/report.hpp"
#include "experiment/storage/file_name.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/error.hpp"
#include "framework/output_files.hpp"

extern char** environ;

namespace pride::cli {
namespace {

namespace fs = std::filesystem;

/// `text` with every `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size())
        text.replace(at, from.size(), to);
    return text;
}

/// Runs `python script args...` (posix_spawn, no shell) with its standard error read through a
/// pipe, not a file: on a full disk the reason must still reach the user. Nothing of it is shown
/// on success (library warnings); on failure its last line (the scripts print one), with the
/// scratch folder's name turned into the output folder's, or how it ended.
void run_script(const std::string& python, const std::string& script, const std::vector<std::string>& args,
                const fs::path& scratch, const fs::path& folder) {
    const std::string name = fs::path(script).filename().string();
    std::vector<std::string> words{python, script};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    std::vector<std::string> env{"PYTHONWARNINGS=ignore", "MPLBACKEND=Agg"};
    for (char** e = environ; *e; ++e)
        if (std::strncmp(*e, "PYTHONWARNINGS=", 15) != 0 && std::strncmp(*e, "MPLBACKEND=", 11) != 0)
            env.emplace_back(*e);
    std::vector<char*> envp;
    for (auto& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);

    int pipe_fds[2];
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0)
        throw InputError("--plots", name + ": cannot start: " + std::strerror(errno));
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
    pid_t pid = 0;
    const int spawned = ::posix_spawnp(&pid, python.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    ::close(pipe_fds[1]);
    if (spawned != 0) {
        ::close(pipe_fds[0]);
        throw InputError("--plots", name + ": cannot start " + python + ": " + std::strerror(spawned));
    }
    std::string errors;
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(pipe_fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        errors.append(buffer, static_cast<std::size_t>(n));
        if (errors.size() > (1u << 16)) errors.erase(0, errors.size() - (1u << 15));  // the end is what counts
    }
    ::close(pipe_fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
    std::string last;
    for (std::size_t begin = 0; begin < errors.size();) {
        const std::size_t end = std::min(errors.find('\n', begin), errors.size());
        if (end > begin) last = errors.substr(begin, end - begin);
        begin = end + 1;
    }
    last = replaced(last, scratch.string(), folder.string());
    if (!last.empty()) throw InputError(last.rfind(name, 0) == 0 ? "--plots: " + last : last);
    if (WIFSIGNALED(status))
        throw InputError("--plots", fmt::format("{} was killed by signal {} ({})", name, WTERMSIG(status),
                                                ::strsignal(WTERMSIG(status))));
    throw InputError("--plots", fmt::format("{} failed with exit status {} and no message", name,
                                            WIFEXITED(status) ? WEXITSTATUS(status) : -1));
}

/// Draws the figures of `data` with scripts/plot_campaign.py (Debian's python3, the one
/// python3-matplotlib serves) and, with the campaign's precisions, scripts/plot_ecdf.py on the
/// ECDF curves computed here (experiment/report/coco.hpp, written to DIR/ecdf.json, so the plots
/// and the tables share one definition). The scripts write into a scratch folder; every file is
/// then taken into `files`, so the figures are complete or absent like every output.
void plot(const std::string& store, const std::string& folder, const report::ReportData& data, OutputFiles& files) {
    const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    const std::string script = std::string(PRIDE_SCRIPTS_DIR) + "/plot_campaign.py";
    require(fs::exists(script), "--plots", script + " is missing");
    const std::string check = "'" + python + "' -c 'import matplotlib' >/dev/null 2>&1";
    require(std::system(check.c_str()) == 0, "--plots",
            "needs python3 with matplotlib (apt-get install python3-matplotlib)");
    const fs::path target(folder);
    fs::path scratch;
    try {
        files.output_folder(target);
        scratch = files.scratch_folder(target);
    } catch (const InputError& e) {
        throw InputError("--plots", e.what());
    }
    const fs::path figures = scratch / "figures";
    const auto unwritable = [&](const std::string& why) {
        return InputError("--plots", target.string() + ": cannot write into the folder: " + why);
    };
    std::error_code ec;
    fs::create_directory(figures, ec);
    if (ec) throw unwritable(ec.message());
    // The problems' file names, as every output names files after ids ("x/y" and "x_y" apart), in
    // a file for the script only (in the scratch folder, removed with it).
    std::set<std::string> ids;
    for (const auto& row : data.rows) ids.insert(row.problem);
    std::string names;
    for (const auto& [id, file] : storage::unique_file_names({ids.begin(), ids.end()}))
        names += (names.empty() ? "" : ", ") + json_string(id) + ": " + json_string(file);
    const fs::path names_file = scratch / "names.json";
    std::ofstream names_out(names_file);
    names_out << "{" << names << "}\n";
    names_out.close();
    if (!names_out) throw unwritable(std::strerror(errno));
    // Each grid problem's map as pride reads it (text, image or map_server file, its unknown cells
    // and inflation as the campaign had them), as a 0/1 matrix for the script, which reads no map
    // format itself; a map file no longer there gets no path figure, as on the HTML page.
    const fs::path maps = scratch / "maps";
    fs::create_directory(maps, ec);
    if (ec) throw unwritable(ec.message());
    std::string map_files;
    for (const html::GridProblemInfo& g : html::read_page_store(store).grids) {
        if (g.map.empty() || !ids.count(g.id) || !fs::exists(g.map)) continue;
        grid::MapReadOptions read;
        read.unknown_free = g.unknown_free;
        read.named_in_file = true;  // the store names it: never standard input
        std::shared_ptr<const grid::GridMap> map;
        try {
            map = engine::load_map(g.map, g.inflate, read);
        } catch (const InputError& e) {
            throw InputError("--plots", "problem '" + g.id + "': " + e.what());
        }
        std::string matrix;
        matrix.reserve(map->size() + static_cast<std::size_t>(map->height()));
        for (int y = 0; y < map->height(); ++y) {
            for (int x = 0; x < map->width(); ++x) matrix += map->free(grid::Cell{x, y}) ? '0' : '1';
            matrix += '\n';
        }
        const fs::path file = maps / (std::to_string(std::distance(ids.begin(), ids.find(g.id))) + ".txt");
        std::ofstream out(file);
        out << matrix;
        out.close();
        if (!out) throw unwritable(std::strerror(errno));
        map_files += (map_files.empty() ? "" : ", ") + json_string(g.id) + ": " + json_string(file.string());
    }
    const fs::path maps_file = scratch / "maps.json";
    std::ofstream maps_out(maps_file);
    maps_out << "{" << map_files << "}\n";
    maps_out.close();
    if (!maps_out) throw unwritable(std::strerror(errno));
    std::vector<std::string> args{store,    figures.string(),   "--names", names_file.string(),
                                  "--maps", maps_file.string(), "--uri",   storage::read_only_uri(store)};
    if (data.raw) args.push_back("--raw");
    run_script(python, script, args, figures, target);
    if (data.coco && !data.coco->curves.empty()) {
        const std::string ecdf_script = std::string(PRIDE_SCRIPTS_DIR) + "/plot_ecdf.py";
        require(fs::exists(ecdf_script), "--plots", ecdf_script + " is missing");
        OutputFiles::File& json = files.create(target / "ecdf.json");  // an output too, read at its temporary name
        json.write(report::coco::ecdf_json(data.campaign, *data.coco));
        json.close();
        run_script(python, ecdf_script, {json.written_at(), figures.string()}, figures, target);
    }
    std::vector<fs::path> made;
    for (const auto& e : fs::directory_iterator(figures)) made.push_back(e.path().filename());
    std::sort(made.begin(), made.end());
    for (const auto& f : made) files.adopt(figures / f, target / f);
}

}  // namespace

int report_command(const ReportOptions& o, std::ostream& out) {
    const bool cec = o.format == "cec" || o.format == "cec-csv";
    const bool rw = o.format == "cec2020rw" || o.format == "cec2020rw-csv";
    require(o.format == "md" || o.format == "csv" || o.format == "latex" || o.format == "ert-csv" ||
                o.format == "functions-csv" || cec || rw,
            "--format",
            "expected md, csv, latex, ert-csv, functions-csv, cec, cec-csv, cec2020rw or cec2020rw-csv, got '" +
                o.format + "'");
    OutputFiles files;  // committed once what is printed was printed
    if (!o.html.empty()) {
        // The page holds the tables itself; what is printed is where it is.
        require(o.format == "md", "--format", o.format + " is printed without --html; --html writes the page alone");
        require(o.stores.size() == 1, "--html", "draws one store; join several into one with pride merge first");
        require(o.plots.empty(), "--plots", "give --plots or --html, not both (the page has its own figures)");
        const html::PageSummary page =
            html::write_report_page(o.stores.front(), o.html, report::ReportOptions{o.raw}, files);
        print_then_commit(out, page.index + ": the report, with " + std::to_string(page.figures) + " figures\n", files);
        return 0;
    }
    if (cec || rw) {
        // The CEC competitions' table alone (experiment/report/cec.hpp): no comparison, no figures.
        require(o.plots.empty(), "--plots", "draws the comparison report's figures; give --format md, csv or latex");
        require(!o.raw, "--raw",
                rw ? "the cec2020rw tables are of values f already; leave --raw out"
                   : "gives values f; the CEC table is of errors f - f* (give --format md, csv or latex)");
        const std::string name = o.stores.size() == 1 ? o.stores.front() : std::string("report");
        if (rw) {
            // The CEC 2020 real-world competition's tables and score (experiment/report/cec2020rw_table.hpp).
            const auto table = report::cec2020rw::make_table(report::read_stores(o.stores), name);
            print_then_commit(out,
                              o.format == "cec2020rw" ? report::cec2020rw::render_markdown(table)
                                                      : report::cec2020rw::render_csv(table),
                              files);
            return 0;
        }
        const report::cec::Table table = report::cec::make_table(report::read_stores(o.stores), name);
        print_then_commit(out, o.format == "cec" ? report::cec::render_markdown(table) : report::cec::render_csv(table),
                          files);
        return 0;
    }
    // The whole store is read and checked before any figure is drawn from it.
    require(o.plots.empty() || o.stores.size() == 1, "--plots",
            "draws one store; join several into one with pride merge first");
    const report::ReportData data = report::load_report(o.stores, report::ReportOptions{o.raw});
    require(o.format != "ert-csv" || data.coco, "--format ert-csv",
            o.stores.front() + ": records no target hits (no precisions, or no run on a problem with a known optimum)");
    const std::string text = o.format == "csv"             ? report::render_csv(data)
                             : o.format == "ert-csv"       ? report::render_ert_csv(data)
                             : o.format == "functions-csv" ? report::render_functions_csv(data)
                             : o.format == "md"            ? report::render_markdown(data)
                                                           : report::render_latex(data);
    if (!o.plots.empty()) plot(o.stores.front(), o.plots, data, files);
    print_then_commit(out, text, files);
    return 0;
}

}  // namespace pride::cli
