#include "experiment/report/coco_export.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "experiment/storage/file_name.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/error.hpp"
#include "framework/output_files.hpp"

#ifndef PRIDE_VERSION
#define PRIDE_VERSION "unknown"
#endif

namespace pride::report {
namespace {

// logger_bbob.c's header of every run's block in .dat and .tdat (Fopt printed with %13.12e).
constexpr const char* kHeader =
    "% f evaluations | g evaluations | best noise-free fitness - Fopt ({:13.12e}) + sum g_i+ | measured fitness | "
    "best measured fitness or single-digit g-values | x1 | x2...\n";

/// max(best, f_opt) - f_opt, as COCO's logger clamps it (+inf stays +inf).
double precision(double best, double f_opt) {
    return std::isfinite(best) ? std::max(best, f_opt) - f_opt : best;
}

/// The COCO suites a run can be written for: bbob and bbob-mixint (whose logger is bbob's), and
/// bbob-constrained, whose runs' traces hold COCO's logged value max(f, f_opt) + sum g_i+
/// (framework/run_state.hpp) and count one f and one constraint evaluation per evaluation.
bool coco_suite(const std::string& suite) {
    return suite == "bbob" || suite == "bbob-mixint" || suite == "bbob-constrained";
}

/// One data line as logger_bbob_output writes it without x, on a line COCO writes without
/// constraint values (its last): "%lu %lu %+10.9e %+10.9e %+10.9e", the f and g evaluations, the
/// best value - f_opt, the current (here the best) value and the best value.
std::string line(std::int64_t evaluations, bool constrained, double best, double f_opt) {
    // COCO writes the logged value's difference as it is (its value is never below f_opt) but
    // clamps an unconstrained best value first.
    const double above = constrained ? best - f_opt : precision(best, f_opt);
    return fmt::format("{} {} {:+10.9e} {:+10.9e} {:+10.9e}\n", evaluations, constrained ? evaluations : 0, above, best,
                       best);
}

/// A run's block: its header, the trace's lines, and (logger_bbob_free) a last line at the run's
/// last evaluation when the trace's last line is not there (a constrained run's trace ends there).
void write_block(OutputFiles::File& out, const std::vector<TracePoint>& trace, const storage::StoredRun& r,
                 double f_opt, bool constrained) {
    std::string block = fmt::format(kHeader, f_opt);
    for (const auto& t : trace) block += line(t.evaluations, constrained, t.best, f_opt);
    const double best = r.best.value_or(INFINITY);
    if (trace.empty() || trace.back().evaluations != r.evaluations) block += line(r.evaluations, false, best, f_opt);
    out.write(block);
}

struct Run {
    std::int64_t instance = 0, seed = 0;
    const storage::StoredRun* run = nullptr;
    double f_opt = 0;
};

}  // namespace

CocoExportSummary export_coco(const std::string& store_path, const std::string& folder) {
    OutputFiles files;
    CocoExportSummary summary = export_coco(store_path, folder, files);
    files.commit();
    return summary;
}

CocoExportSummary export_coco(const std::string& store_path, const std::string& folder, OutputFiles& files) {
    require(!folder.empty(), "COCO export", "name the folder to write");
    const storage::CampaignStore store = storage::read_store(store_path);
    if (!store.problems) throw storage::DamagedStore(store_path, "it has no table problems");
    std::map<std::string, const storage::StoredProblem*> problems;
    for (const auto& p : *store.problems) problems[p.id] = &p;

    // algorithm -> fid -> dim -> runs, by instance then seed: one entry per run in the .info line,
    // in the order of the runs' blocks in the .dat and .tdat files, which is how cocopp pairs them.
    std::map<std::string, std::map<std::int64_t, std::map<std::int64_t, std::vector<Run>>>> runs;
    CocoExportSummary summary;
    summary.folder = folder;
    const storage::StoredRun* first = nullptr;  // the first run of the suite written, for the mixed-suite error
    for (const storage::StoredRun& r : store.runs) {
        const auto it = problems.find(r.problem);
        const storage::StoredProblem* p = it == problems.end() ? nullptr : it->second;
        if (!p || !p->suite || !coco_suite(*p->suite) || !p->fid || !p->f_opt || p->instance < 1) {
            ++summary.skipped;
            continue;
        }
        // cocopp reads a folder as one suite's data (its .info's first suite = '...' chooses the
        // testbed), and a constrained run's evaluations count twice: two suites cannot share a folder.
        if (summary.suite.empty()) {
            summary.suite = *p->suite;
            first = &r;
        }
        require(*p->suite == summary.suite, store_path,
                fmt::format("holds runs of two COCO suites, {} (problem '{}') and {} (problem '{}'); COCO's data of "
                            "one export is one suite's: run each suite's campaign into a store of its own",
                            summary.suite, first->problem, *p->suite, r.problem));
        const bool constrained = *p->suite == "bbob-constrained";
        require(!r.trace_targets.empty() && (!constrained || (r.trace_targets.back().evaluations == r.evaluations &&
                                                              !r.trace_evaluations.empty() &&
                                                              r.trace_evaluations.back().evaluations == r.evaluations)),
                store_path,
                fmt::format("run (problem '{}', algorithm '{}', seed {}) has no COCO trace{} (stored before pride kept "
                            "one); run the campaign again into a new store to export it",
                            r.problem, r.algorithm, r.seed, constrained ? " of COCO's constrained values" : ""));
        runs[r.algorithm][*p->fid][p->dim].push_back({p->instance, r.seed, &r, *p->f_opt});
    }
    require(!runs.empty(), store_path,
            "holds no run on the bbob, bbob-mixint or bbob-constrained suites (COCO's data format is for their "
            "campaigns: [[suite]] name = \"bbob\", \"bbob-mixint\" or \"bbob-constrained\")");
    const bool constrained = summary.suite == "bbob-constrained";

    std::vector<std::string> ids;
    for (const auto& entry : runs) ids.push_back(entry.first);
    const auto folders = storage::unique_file_names(ids);
    summary.algorithms = runs.size();
    files.output_folder(folder);
    for (auto& [algorithm, by_fid] : runs) {
        const std::filesystem::path dir = std::filesystem::path(folder) / folders.at(algorithm);
        for (auto& [fid, by_dim] : by_fid) {
            const std::string data_folder = fmt::format("data_f{}", fid);
            files.make_folder(dir / data_folder);
            std::string info;
            bool first_dim = true;
            for (auto& [dim, dim_runs] : by_dim) {
                std::sort(dim_runs.begin(), dim_runs.end(), [](const Run& a, const Run& b) {
                    return std::tie(a.instance, a.seed) < std::tie(b.instance, b.seed);
                });
                const std::string stem = fmt::format("{}/bbobexp_f{}_DIM{}", data_folder, fid, dim);
                // logger_bbob_open_info_file: the header, a comment line, the data file, then
                // ", instance:evaluations|final precision" per run (%.1e).
                info += fmt::format(
                    "{}suite = '{}', funcId = {}, DIM = {}, Precision = {:.3e}, algId = '{}', coco_version = "
                    "'pride {}', logger = 'bbob', data_format = 'bbob-new2'\n% pride campaign {}, algorithm {}\n{}.dat",
                    first_dim ? "" : "\n", summary.suite, fid, dim, 1e-8, folders.at(algorithm), PRIDE_VERSION,
                    store.name, algorithm, stem);
                first_dim = false;
                OutputFiles::File& dat = files.create(dir / (stem + ".dat"));
                OutputFiles::File& tdat = files.create(dir / (stem + ".tdat"));
                for (const Run& run : dim_runs) {
                    write_block(dat, run.run->trace_targets, *run.run, run.f_opt, constrained);
                    write_block(tdat, run.run->trace_evaluations, *run.run, run.f_opt, constrained);
                    // logger_bbob_free: the f evaluations and the final best value - f_opt (a
                    // constrained run's: COCO's logged value, its trace's last).
                    const double final_precision = constrained ? run.run->trace_targets.back().best - run.f_opt
                                                               : precision(run.run->best.value_or(INFINITY), run.f_opt);
                    info += fmt::format(", {}:{}|{:.1e}", run.instance, run.run->evaluations, final_precision);
                    ++summary.runs;
                }
                dat.close();
                tdat.close();
                summary.files += 2;
            }
            files.write(dir / fmt::format("bbobexp_f{}.info", fid), info + "\n");
            ++summary.files;
        }
    }
    return summary;
}

}  // namespace pride::report
