#include "experiment/report/ioh_export.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "experiment/storage/file_name.hpp"
#include "experiment/storage/reader.hpp"
#include "framework/error.hpp"
#include "framework/output_files.hpp"

namespace pride::report {
namespace {

/// A value as IOHexperimenter's FlatFile logger writes it: "None" where it has none (its RawY
/// property gives no value for an infinite f(x), and the logger writes its no-value text, "None").
std::string value(double v) {
    return std::isfinite(v) ? fmt::format("{:.17g}", v) : "None";
}

/// IOHexperimenter's names of the BBOB functions, by fid (include/ioh/problem/bbob/*.hpp, the
/// name each class passes to its problem), so that IOHanalyzer shows them as it shows its own.
const char* ioh_bbob_name(std::int64_t fid) {
    static const char* const names[] = {
        "Sphere",           "Ellipsoid",     "Rastrigin",     "BuecheRastrigin",    "LinearSlope",
        "AttractiveSector", "StepEllipsoid", "Rosenbrock",    "RosenbrockRotated",  "EllipsoidRotated",
        "Discus",           "BentCigar",     "SharpRidge",    "DifferentPowers",    "RastriginRotated",
        "Weierstrass",      "Schaffers10",   "Schaffers1000", "GriewankRosenbrock", "Schwefel",
        "Gallagher101",     "Gallagher21",   "Katsuura",      "LunacekBiRastrigin"};
    return fid >= 1 && fid <= 24 ? names[fid - 1] : nullptr;
}

/// The function ids, disjoint across kinds so that no two problems share one in IOHanalyzer (which
/// tells functions apart by id): BBOB's fid (1-24, IOH's own), 100 + N for the classic suite's F_N
/// (Yao's F1 is not BBOB's f1), 200 + N for CEC 2017's, 300 + N for CEC 2022's, 1000 + the
/// position in the campaign for any other problem.
constexpr std::int64_t other_ids = 1000;

std::int64_t suite_ids(const std::string& suite) {
    return suite == "cec2017" ? 200 : suite == "cec2022" ? 300 : 100;
}

/// One IOHprofiler function: a .info file and, per dimension, a .dat file.
struct Function {
    IohFunction fn;
    // dim -> the runs, each with the instance it names
    std::map<std::int64_t, std::vector<std::pair<std::int64_t, const storage::StoredRun*>>> runs;
};

}  // namespace

std::string ioh_quoted(const std::string& name) {
    std::string s;
    for (const char c : name) s += c == '"' || c == '\n' || c == '\r' ? '_' : c;
    return s;
}

IohFunction ioh_function(const storage::StoredProblem& p, std::size_t position) {
    IohFunction fn;
    fn.in_suite = p.suite && p.fid;
    const bool bbob = fn.in_suite && *p.suite == "bbob" && ioh_bbob_name(*p.fid);
    fn.id = bbob          ? *p.fid
            : fn.in_suite ? suite_ids(*p.suite) + *p.fid
                          : other_ids + static_cast<std::int64_t>(position + 1);
    fn.name = bbob ? ioh_bbob_name(*p.fid) : fn.in_suite ? p.function.value_or(p.id) : p.id;
    // IOHexperimenter's name of the BBOB suite; problems outside a suite are pride's.
    fn.suite = !fn.in_suite ? "pride" : *p.suite == "bbob" ? "BBOB" : *p.suite;
    return fn;
}

ExportSummary export_ioh(const std::string& store_path, const std::string& folder) {
    OutputFiles files;
    ExportSummary summary = export_ioh(store_path, folder, files);
    files.commit();
    return summary;
}

ExportSummary export_ioh(const std::string& store_path, const std::string& folder, OutputFiles& files) {
    require(!folder.empty(), "IOH export", "name the folder to write");
    const storage::CampaignStore store = storage::read_store(store_path);
    // The function ids and dimensions are in this table only.
    if (!store.problems) throw storage::DamagedStore(store_path, "it has no table problems");
    require(!store.runs.empty(), store_path, "holds no runs yet (run pride bench first)");
    std::map<std::string, std::map<std::string, std::vector<const storage::StoredRun*>>> runs;  // algorithm -> problem
    for (const storage::StoredRun& r : store.runs) runs[r.algorithm][r.problem].push_back(&r);

    ExportSummary summary;
    summary.folder = folder;
    summary.algorithms = runs.size();
    std::vector<std::string> ids;
    for (const auto& entry : runs) ids.push_back(entry.first);
    const auto folders = storage::unique_file_names(ids);
    files.output_folder(folder);
    for (const auto& [algorithm, by_problem] : runs) {
        // Suite problems (a suite and a fid, e.g. bbob) as IOHexperimenter writes them: one
        // function per fid (file IOHprofiler_f<fid>_<function>), all its instances and seeds as
        // the runs of one .dat per dimension, each run named by its instance. Other problems keep
        // their place in the campaign as function id, one function per problem, runs by seed.
        std::map<std::tuple<int, std::int64_t, std::string>, Function> functions;
        for (std::size_t f = 0; f < store.problems->size(); ++f) {
            const storage::StoredProblem& p = (*store.problems)[f];
            const auto it = by_problem.find(p.id);
            if (it == by_problem.end()) continue;
            const IohFunction id = ioh_function(p, f);
            Function& fn = functions[{id.in_suite ? 0 : 1, id.id, id.name}];
            fn.fn = id;
            for (const storage::StoredRun* r : it->second)
                fn.runs[p.dim].emplace_back(id.in_suite ? p.instance : r->seed, r);
        }
        const std::filesystem::path dir = std::filesystem::path(folder) / folders.at(algorithm);
        files.make_folder(dir);
        for (const auto& [key, function] : functions) {
            const IohFunction& fn = function.fn;
            const std::string stem = fmt::format("f{}_{}", fn.id, storage::file_name(fn.name));
            const std::string data_folder = "data_" + stem;
            files.make_folder(dir / data_folder);
            std::string info;
            bool first = true;
            for (const auto& [dim, dim_runs] : function.runs) {
                const std::string dat = fmt::format("IOHprofiler_f{}_DIM{}.dat", fn.id, dim);
                OutputFiles::File& d = files.create(dir / data_folder / dat);
                std::string block;
                // As IOHexperimenter's Analyzer (v1, the .info format) writes them: a header line per
                // dimension, "%", the data file, then "instance:evaluations|best" per run.
                info += fmt::format(
                    "{}suite = \"{}\", funcId = {}, funcName = \"{}\", DIM = {}, maximization = \"F\", algId = "
                    "\"{}\", algInfo = \"campaign {}\"\n%\n{}/{}",
                    first ? "" : "\n", ioh_quoted(fn.suite), fn.id, ioh_quoted(fn.name), dim, ioh_quoted(algorithm),
                    ioh_quoted(store.name), data_folder, dat);
                first = false;
                for (const auto& [number, r] : dim_runs) {
                    // One block per run: the best value after each iteration, at its evaluation
                    // count, in the five columns of IOHexperimenter's old data format (no
                    // transformation here: af(x)+b = f(x)).
                    block +=
                        "\"function evaluation\" \"current f(x)\" \"best-so-far f(x)\" \"current af(x)+b\" "
                        "\"best af(x)+b\"\n";
                    // Rows start at the first finite value: IOHanalyzer reads a row as a value reached,
                    // and before a feasible one there is none (a run with none writes no row).
                    for (std::size_t k = 0; k < r->history.size() && k < r->history_evaluations.size(); ++k) {
                        if (!std::isfinite(r->history[k])) continue;
                        const std::string v = value(r->history[k]);
                        block += fmt::format("{} {} {} {} {}\n", r->history_evaluations[k], v, v, v, v);
                    }
                    if (block.size() >= (1u << 16)) {  // written as it grows: memory stays small
                        d.write(block);
                        block.clear();
                    }
                    info += fmt::format(", {}:{}|{}", number, r->evaluations,
                                        r->best ? fmt::format("{:.17g}", *r->best) : std::string("None"));
                }
                d.write(block);
                d.close();
                ++summary.files;
            }
            files.write(dir / ("IOHprofiler_" + stem + ".info"), info + "\n");
            ++summary.files;
        }
    }
    return summary;
}

}  // namespace pride::report
