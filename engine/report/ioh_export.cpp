#include "engine/report/ioh_export.hpp"

#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <vector>

#include "engine/report/store.hpp"
#include "framework/error.hpp"

namespace pride::report {
namespace {

/// A name as a file name: anything but letters, digits, '-' and '.' becomes '_'.
std::string safe(const std::string& name) {
    std::string s = name;
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.') c = '_';
    return s;
}

}  // namespace

ExportSummary export_ioh(const std::string& store_path, const std::string& folder) {
    require(!folder.empty(), "IOH export", "name the folder to write");
    const CampaignStore store = read_store(store_path);
    // The function ids are the problems' places in the campaign, which only this table keeps.
    if (!store.problems) throw DamagedStore(store_path, "it has no table problems");
    require(!store.runs.empty(), store_path, "holds no runs yet (run pride bench first)");
    std::map<std::string, std::map<std::string, std::vector<const StoredRun*>>> runs;  // algorithm -> problem
    for (const StoredRun& r : store.runs) runs[r.algorithm][r.problem].push_back(&r);

    ExportSummary summary;
    summary.folder = folder;
    summary.algorithms = runs.size();
    for (const auto& [algorithm, by_problem] : runs) {
        const std::filesystem::path dir = std::filesystem::path(folder) / safe(algorithm);
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        require(!ec, dir.string(), "cannot create the folder");
        for (std::size_t f = 0; f < store.problems->size(); ++f) {
            const auto& [problem, dim] = (*store.problems)[f];
            const auto it = by_problem.find(problem);
            if (it == by_problem.end()) continue;
            const std::string id = std::to_string(f + 1), name = safe(problem);
            const std::string data_folder = "data_f" + id + "_" + name;
            const std::string dat = "IOHprofiler_f" + id + "_DIM" + std::to_string(dim) + ".dat";
            std::filesystem::create_directories(dir / data_folder, ec);
            std::ofstream d(dir / data_folder / dat);
            std::string runs_line;
            for (const StoredRun* r : it->second) {
                // One block per run: the best value after each iteration, at its evaluation count.
                d << "\"function evaluation\" \"current f(x)\" \"best-so-far f(x)\"\n";
                for (std::size_t k = 0; k < r->history.size() && k < r->history_evaluations.size(); ++k)
                    d << fmt::format("{} {:.17g} {:.17g}\n", r->history_evaluations[k], r->history[k], r->history[k]);
                runs_line += fmt::format(", {}:{}|{:.17g}", r->seed, r->evaluations,
                                         r->best.value_or(std::numeric_limits<double>::infinity()));
            }
            std::ofstream info(dir / ("IOHprofiler_f" + id + "_" + name + ".info"));
            info << fmt::format(
                "suite = 'pride', funcId = {}, funcName = '{}', DIM = {}, maximization = 'F', algId = "
                "'{}', algInfo = 'campaign {}'\n%\n{}/{}{}\n",
                id, problem, dim, algorithm, store.name, data_folder, dat, runs_line);
            require(d.good() && info.good(), dir.string(), "cannot write the files");
            summary.files += 2;
        }
    }
    return summary;
}

}  // namespace pride::report
