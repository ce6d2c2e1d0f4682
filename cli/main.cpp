// pride: the command line of the framework (docs/cli.md). Exit status 0 on success, 2 on
// bad input (one line on stderr naming what and where), 1 on an internal failure.
#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "cli/campaign.hpp"
#include "cli/commands.hpp"
#include "cli/export.hpp"
#include "cli/flags.hpp"
#include "cli/front.hpp"
#include "cli/grid_commands.hpp"
#include "cli/pareto.hpp"
#include "cli/report.hpp"
#include "cli/roughset.hpp"
#include "cli/stderr.hpp"
#include "engine/registry.hpp"
#include "experiment/storage/merge.hpp"
#include "framework/error.hpp"

namespace {

bool error_printed = false;  // the one line of an error is on stderr already

/// Standard output flushed and checked: a full disk or a closed stream is a failure (exit 2, one
/// line), never a silent success with lost output.
int finish_output(int status) {
    std::cout.flush();
    const bool failed = !std::cout.good() || std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
    if (failed) {
        // A command that failed has said why (perhaps this very failure): one line, its status.
        if (error_printed) return status;
        const int e = errno;
        pride::cli::print_stderr("pride: cannot write to standard output: {}\n",
                                 e != 0 ? std::strerror(e) : "write error");
        return 2;
    }
    return status;
}

}  // namespace

int run_main(int argc, char** argv);

int main(int argc, char** argv) {
    // A closed standard output (`>&-`) is refused before anything is done: a file opened later
    // would get its descriptor and receive what is printed.
    if (fcntl(STDOUT_FILENO, F_GETFD) == -1 && errno == EBADF) {
        pride::cli::print_stderr("pride: cannot write to standard output: it is closed\n");
        return 2;
    }
    if (fcntl(STDERR_FILENO, F_GETFD) == -1 && errno == EBADF && open("/dev/null", O_WRONLY) != STDERR_FILENO)
        return 2;  // descriptor 2 kept taken for the same reason
    int status = 0;
    try {
        status = run_main(argc, argv);
    } catch (const std::exception& e) {
        pride::cli::print_stderr("pride: internal error: {}\n", e.what());
        error_printed = true;
        status = 1;
    }
    errno = 0;
    return finish_output(status);
}

int run_main(int argc, char** argv) {
    using namespace pride::cli;
    CLI::App app{"pride: metaheuristic optimisation with pluggable problems"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("pride ") + PRIDE_VERSION, "print the version and exit");

    // The algorithm names of the help texts, from the registry.
    std::string box_names, all_names, mo_names;
    for (const auto& a : pride::engine::algorithms().entries()) {
        if (a.name.find(':') != std::string::npos) continue;
        if (a.multiobjective()) {
            mo_names += (mo_names.empty() ? "" : ", ") + a.name;
            continue;
        }
        all_names += (all_names.empty() ? "" : ", ") + a.name;
        if (a.runs(pride::engine::Kind::box)) box_names += (box_names.empty() ? "" : ", ") + a.name;
    }
    RunOptions run;
    auto* run_cmd = app.add_subcommand("run", "one run of an algorithm on a continuous problem");
    run_cmd->add_option("--problem", run.problem, "problem name (see 'pride list')")->required();
    run_cmd->add_option("--dim", run.dim, "dimension")->required()->check(integer_in(1, max_count));
    run_cmd
        ->add_option("--instance", run.instance,
                     "instance: 0 = the function as defined (default; BBOB: 1), K >= 1 shifted and rotated")
        ->check(integer_in(0, max_instance));
    run_cmd->add_option("--algo", run.algo, box_names + " or nlopt:NAME (see 'pride list')")->required();
    auto* evals = run_cmd->add_option("--evals", run.budget.evaluations, "evaluation budget (default 10000 * dim)")
                      ->check(integer_in(1, max_count));
    run_cmd->add_option("--iters", run.budget.iterations, "iteration limit")
        ->excludes(evals)
        ->check(integer_in(0, max_count));
    run_cmd->add_option("--target", run.budget.target, "stop once the best value is <= this")->check(finite_in());
    run_cmd->add_option("--wall-ms", run.budget.wall_ms, "stop after this many milliseconds")->check(finite_in());
    run_cmd->add_option("--pop", run.pop,
                        "population size (NLopt: evaluations per recorded iteration; its range: pride list)");
    run_cmd->add_option("--seed", run.seed, "random seed (default 1)")->check(integer_in(0, max_seed));
    run_cmd
        ->add_option("--threads", run.budget.threads,
                     "threads evaluating a population (default 1; continuous functions use one: they are cheaper "
                     "than a thread's wake-up)")
        ->check(integer_in(1, 256));
    run_cmd->add_option("--param", run.params, "algorithm parameter NAME=VALUE (repeatable)");
    run_cmd->add_flag("--json", run.json, "print one JSON object");

    EvalOptions eval;
    auto* eval_cmd = app.add_subcommand("eval", "the value of a continuous problem at given points");
    eval_cmd->add_option("--problem", eval.problem, "problem name (see 'pride list')")->required();
    eval_cmd->add_option("--x", eval.x, "V1,V2,... or - to read one point per line from stdin")->required();
    eval_cmd->add_option("--dim", eval.dim, "check that every point has this many coordinates")
        ->check(integer_in(1, max_count));
    eval_cmd->add_option("--instance", eval.instance, "instance (as for pride run)")
        ->check(integer_in(0, max_instance));
    eval_cmd->add_option("--seed", eval.seed, "the noise stream of a noisy function (default 0)")
        ->check(integer_in(0, max_seed));

    PathOptions path;
    auto* path_cmd = app.add_subcommand(
        "path", "one run on a grid map (A*, the exact optimum, or a box algorithm through an encoding)");
    path_cmd
        ->add_option("--map", path.map,
                     "Moving AI .map, 0/1 matrix (CSV too), PNG/PGM image or ROS map_server YAML file")
        ->required()
        ->check(a_path());
    // One of --start and --start-world (and of --goal, --goal-world): plan_path says which is missing.
    auto* path_start =
        path_cmd->add_option("--start", path.start, "start cell X,Y (x: column from the left, y: row from the top)");
    path_cmd
        ->add_option("--start-world", path.start_world,
                     "start point X,Y in metres (maps with a world frame: ROS map_server YAML); the cell holding it")
        ->excludes(path_start);
    auto* path_goal = path_cmd->add_option("--goal", path.goal, "goal cell X,Y");
    path_cmd->add_option("--goal-world", path.goal_world, "goal point X,Y in metres (as --start-world)")
        ->excludes(path_goal);
    path_cmd->add_flag("--unknown-free", path.unknown_free,
                       "unknown cells of images and map_server maps are free (default: blocked)");
    path_cmd->add_option("--algo", path.algo, all_names + " or nlopt:NAME (see 'pride list')")->required();
    path_cmd->add_option(
        "--objective", path.objective,
        "cells, length, weighted, iqga or hswoa (default: length for a planner of polylines, cells otherwise)");
    path_cmd->add_option("--encoding", path.encoding,
                         "line, free or chain (default: the algorithm's native one: chain for iqga, iaga, icga and the "
                         "woa family, line for the others)");
    path_cmd->add_option("--connector", path.connector, "repair (default) or penalty");
    path_cmd->add_option(
        "--init", path.init,
        "uniform, walk (random feasible walks), rules (rough-set rule walks, Wan and Gao 2022) or sitp (SITP walks, "
        "Zhang et al. 2025; also for --encoding chain); default: rules for ilso, uniform for the others");
    path_cmd->add_option("--pop", path.pop, "population size (default 20; its range: pride list)");
    auto* path_iters =
        path_cmd
            ->add_option("--iters", path.budget.iterations, "iteration limit (default 50 when --evals is not given)")
            ->check(integer_in(0, max_count));
    path_cmd->add_option("--evals", path.budget.evaluations, "evaluation limit")
        ->excludes(path_iters)
        ->check(integer_in(1, max_count));
    path_cmd->add_option("--seed", path.seed, "random seed (default 1)")->check(integer_in(0, max_seed));
    path_cmd
        ->add_option("--threads", path.budget.threads,
                     "threads evaluating a population of genotypes (line and free encodings; default 1); the "
                     "same result as one thread")
        ->check(integer_in(1, 256));
    path_cmd->add_option("--inflate", path.inflate, "obstacle inflation radius in cells (default 0)")
        ->check(integer_in(0, 1000));
    path_cmd->add_option("--waypoints", path.waypoints, "waypoints of the free encoding (default 3)")
        ->check(integer_in(1, 1000));
    path_cmd->add_option("--weights", path.weights, "L,T,A weights of the weighted objective (default 1,1,0.1)");
    path_cmd->add_option("--lambda", path.lambda, "turn weight of the hswoa objective (default 1)")
        ->check(finite_in(0, pride::engine::max_weight));
    path_cmd->add_flag("--corner-cutting", path.corner_cutting, "allow diagonal steps past a blocked corner");
    path_cmd->add_flag("--oracle", path.oracle, "add the exact optimum and the gap to it");
    path_cmd->add_flag("--gaps", path.gaps,
                       "add the shortest grid and any-angle lengths and the path's length gaps to them");
    path_cmd->add_flag("--json", path.json, "print one JSON object");
    path_cmd->add_option("--svg", path.svg, "draw the map and the path(s) to this SVG file")->check(a_path());
    path_cmd->add_option("--png", path.png, "draw the map and the path(s) to this PNG file")->check(a_path());
    path_cmd->add_option("--param", path.params, "algorithm parameter NAME=VALUE (repeatable)");

    ParetoOptions pareto;
    auto* pareto_cmd = app.add_subcommand(
        "pareto", "the exact Pareto front of length, turns and angle penalty on a grid map, with a path each");
    pareto_cmd->add_option("--map", pareto.map, "Moving AI .map or 0/1 matrix file")->required()->check(a_path());
    pareto_cmd->add_option("--start", pareto.start, "start cell X,Y (x: column from the left, y: row from the top)")
        ->required();
    pareto_cmd->add_option("--goal", pareto.goal, "goal cell X,Y")->required();
    pareto_cmd
        ->add_option("--objectives", pareto.objectives,
                     "two to four of length, turns, angle, clearance, comma-separated")
        ->required();
    pareto_cmd->add_flag("--unknown-free", pareto.unknown_free,
                         "unknown cells of images and map_server maps are free (default: blocked)");
    pareto_cmd->add_option("--inflate", pareto.inflate, "obstacle inflation radius in cells (default 0)")
        ->check(integer_in(0, 1000));
    pareto_cmd->add_flag("--corner-cutting", pareto.corner_cutting, "allow diagonal steps past a blocked corner");
    pareto_cmd->add_flag("--json", pareto.json, "print one JSON object");
    pareto_cmd->add_option("--svg", pareto.svg, "draw the map and every path of the front to this SVG file")
        ->check(a_path());
    pareto_cmd->add_option("--png", pareto.png, "draw the map and every path of the front to this PNG file")
        ->check(a_path());
    pareto_cmd
        ->add_option("--plot", pareto.plot,
                     "draw the front in objective space (the first two objectives as given) to this SVG file")
        ->check(a_path());

    FrontOptions front;
    auto* front_cmd = app.add_subcommand(
        "front", "one run of a multi-objective algorithm (ZDT, DTLZ, or a grid with several criteria): its front");
    front_cmd->add_option("--algo", front.algo, mo_names)->required();
    front_cmd->add_option("--problem", front.problem,
                          "zdt1, zdt2, zdt3, zdt4, zdt6, dtlz1-dtlz7, or constrained: constr, srn, tnk, c1-dtlz1, "
                          "c2-dtlz2; real-world: re21-re91, cre21-cre51 (or --map)");
    front_cmd->add_option("--dim", front.dim, "number of variables n (default: the paper's)")
        ->check(integer_in(1, max_count));
    front_cmd->add_option("--map", front.map, "a grid: Moving AI .map or 0/1 matrix file")->check(a_path());
    front_cmd->add_option("--start", front.start, "grids: start cell X,Y");
    front_cmd->add_option("--goal", front.goal, "grids: goal cell X,Y");
    front_cmd->add_option("--objectives", front.objectives,
                          "DTLZ: the number of objectives M (default 3); grids: two to four of length, turns, angle, "
                          "clearance (default length,turns)");
    front_cmd->add_option("--encoding", front.encoding,
                          "grids: line (default), free, or chain (cell chains with the chain operators: nsga2, nsga3)");
    front_cmd->add_option("--init", front.init,
                          "grids on chains: walk (random walks, default) or sitp (Zhang et al. 2025)");
    front_cmd->add_option("--connector", front.connector, "grids: repair (default) or penalty");
    front_cmd->add_option("--waypoints", front.waypoints, "waypoints of the free encoding (default 3)")
        ->check(integer_in(1, 1000));
    front_cmd->add_flag("--unknown-free", front.unknown_free,
                        "grids: unknown cells of images and map_server maps are free (default: blocked)");
    front_cmd->add_option("--inflate", front.inflate, "obstacle inflation radius in cells (default 0)")
        ->check(integer_in(0, 1000));
    front_cmd->add_flag("--corner-cutting", front.corner_cutting, "allow diagonal steps past a blocked corner");
    auto* front_evals = front_cmd
                            ->add_option("--evals", front.budget.evaluations,
                                         "evaluation budget (default 10000 * n; grids: 50 iterations)")
                            ->check(integer_in(1, max_count));
    front_cmd->add_option("--iters", front.budget.iterations, "iteration limit")
        ->excludes(front_evals)
        ->check(integer_in(0, max_count));
    front_cmd->add_option("--wall-ms", front.budget.wall_ms, "stop after this many milliseconds")->check(finite_in());
    front_cmd->add_option("--pop", front.pop, "population size (its range: pride list)");
    front_cmd->add_option("--seed", front.seed, "random seed (default 1)")->check(integer_in(0, max_seed));
    front_cmd->add_option("--param", front.params, "algorithm parameter NAME=VALUE (repeatable)");
    front_cmd->add_flag("--no-reference", front.no_reference,
                        "skip the reference front and the indicators (a grid's exact front can be costly)");
    front_cmd->add_flag("--json", front.json, "print one JSON object");
    front_cmd->add_option("--svg", front.svg, "grids: draw the map and the front's paths to this SVG file")
        ->check(a_path());
    front_cmd->add_option("--png", front.png, "grids: draw the map and the front's paths to this PNG file")
        ->check(a_path());
    front_cmd
        ->add_option("--plot", front.plot,
                     "draw the set in objective space (the first two objectives), with the reference front, to this "
                     "SVG file")
        ->check(a_path());

    ScenOptions scen;
    auto* scen_cmd = app.add_subcommand("scen", "solve every line of a Moving AI scenario file with A* and compare");
    scen_cmd->add_option("file", scen.file, "the .scen file")->required()->check(a_path());
    scen_cmd->add_option("--map-dir", scen.map_dir, "where the maps are (default: the scenario's folder)")
        ->check(a_path());
    scen_cmd->add_flag("--json", scen.json, "print one JSON object");

    BenchOptions bench;
    auto* bench_cmd = app.add_subcommand("bench", "run a campaign file: every (problem, algorithm, seed), resumable");
    bench_cmd->add_option("config", bench.config, "the campaign file (TOML)")->required()->check(a_path());
    bench_cmd->add_option("--jobs", bench.jobs, "parallel runs (default: the number of cores)")
        ->check(integer_in(1, 1024));
    bench_cmd
        ->add_option("--out", bench.out,
                     "the SQLite store (default: the name of CONFIG with .sqlite, in the working folder)")
        ->check(a_path());
    bench_cmd->add_option("--shard", bench.shard,
                          "K/N: run only part K of N of the campaign's runs (every N-th from the K-th), for a "
                          "campaign split across machines; pride merge joins the parts' stores");

    ReportOptions report;
    auto* report_cmd = app.add_subcommand("report", "comparison tables and statistics from a campaign store");
    report_cmd->add_option("stores", report.stores, "the SQLite store written by pride bench (or several, read as one)")
        ->required()
        ->check(a_path());
    report_cmd->add_option(
        "--format", report.format,
        "md (default), csv, latex, ert-csv (the ERT of a campaign with target precisions), functions-csv (the table "
        "of functions of a suite with instances), or cec "
        "and cec-csv (the CEC competitions' errors f - f* at their checkpoints), cec2020rw and cec2020rw-csv (the "
        "CEC 2020 real-world competition's tables and score)");
    report_cmd->add_option("--plots", report.plots, "write convergence, final-value and path figures (PNG, SVG) here")
        ->check(a_path());
    report_cmd
        ->add_option("--html", report.html,
                     "write the report as one HTML page (index.html, SVG figures beside it) into this folder")
        ->check(a_path());
    report_cmd->add_flag("--raw", report.raw,
                         "the values f as run, also where f_opt is known (default there: the precision f - f_opt)");

    ExportOptions exporting;
    auto* export_cmd =
        app.add_subcommand("export", "a campaign store as IOHprofiler files (IOHanalyzer) or COCO's data (cocopp)");
    export_cmd->add_option("store", exporting.store, "the SQLite store written by pride bench")
        ->required()
        ->check(a_path());
    auto* ioh_option =
        export_cmd->add_option("--ioh", exporting.ioh, "the folder to write IOHprofiler files to")->check(a_path());
    export_cmd
        ->add_option(
            "--coco", exporting.coco,
            "the folder to write COCO's data (.info, .dat, .tdat) of bbob, bbob-mixint or bbob-constrained runs to")
        ->excludes(ioh_option)
        ->check(a_path());

    ImportOptions importing;
    auto* import_cmd =
        app.add_subcommand("import",
                           "published runs (a COCO bbob data set, a CEC 2017 entrant's result files, IOHprofiler "
                           "files) into a store, beside its campaign's runs");
    import_cmd->add_option("store", importing.store, "the SQLite store (created when absent)")
        ->required()
        ->check(a_path());
    auto* coco_option =
        import_cmd
            ->add_option("--coco", importing.coco, "the COCO data set's folder (.info, .dat, .tdat; a .tgz extracted)")
            ->check(a_path());
    auto* cec2017_option =
        import_cmd
            ->add_option("--cec2017", importing.cec2017,
                         "one CEC 2017 entrant's folder (NAME_F_D.txt: 14 checkpoints x 51 runs' errors)")
            ->excludes(coco_option)
            ->check(a_path());
    import_cmd
        ->add_option("--ioh", importing.ioh,
                     "one algorithm's folder of IOHprofiler files (.info, .dat), as pride export --ioh writes it, "
                     "onto the store's problems")
        ->excludes(coco_option)
        ->excludes(cec2017_option)
        ->check(a_path());
    import_cmd->add_option("--name", importing.name, "the published algorithm's name: stored as published:NAME")
        ->required();
    import_cmd->add_option("--citation", importing.citation, "whose runs these are and where they were published")
        ->required();

    std::vector<std::string> merge_inputs;
    std::string merge_out;
    auto* merge_cmd = app.add_subcommand("merge", "join the runs of compatible campaign stores into a new store");
    merge_cmd->add_option("stores", merge_inputs, "two stores or more, written by pride bench")
        ->required()
        ->check(a_path());
    merge_cmd->add_option("--out", merge_out, "the new store to write (it must not exist)")
        ->required()
        ->check(a_path());

    bool list_json = false, list_markdown = false;
    auto* list_cmd = app.add_subcommand("list", "the algorithms, problems, encodings and objectives");
    auto* list_json_flag = list_cmd->add_flag("--json", list_json, "print one JSON object");
    list_cmd->add_flag("--markdown", list_markdown, "print markdown tables (the ones in docs/cli.md)")
        ->excludes(list_json_flag);

    RoughsetOptions roughset;
    auto* roughset_cmd = app.add_subcommand("roughset", "reduce a decision table: core, reducts and minimal rules");
    roughset_cmd->add_option("table", roughset.table, "CSV file: a header of names, the last column the decision")
        ->check(a_path());
    roughset_cmd->add_flag("--grid", roughset.grid, "Wan and Gao's (2022) grid decision table instead of a file");
    roughset_cmd->add_flag("--json", roughset.json, "print one JSON object");

    try {
        const auto subcommands = app.get_subcommands([](const CLI::App*) { return true; });
        const bool known = argc > 1 && std::any_of(subcommands.begin(), subcommands.end(),
                                                   [&](const CLI::App* s) { return s->get_name() == argv[1]; });
        if (argc == 2 && std::string(argv[1]) == "--version") {  // before the check for a subcommand
            std::cout << "pride " << PRIDE_VERSION << "\n";
            return 0;
        }
        if (argc > 1 && argv[1][0] != '-' && !known)
            throw pride::InputError(std::string("unknown subcommand '") + argv[1] +
                                    "' (expected run, eval, list, path, pareto, front, scen, roughset, bench, report, "
                                    "merge, export or import)");
        app.parse(argc, argv);
        if (*run_cmd) return run_command(run, std::cout);
        if (*eval_cmd) return eval_command(eval, std::cin, std::cout);
        if (*list_cmd)
            return list_command(list_json       ? ListFormat::json
                                : list_markdown ? ListFormat::markdown
                                                : ListFormat::text,
                                std::cout);
        if (*path_cmd) return path_command(path, std::cout);
        if (*scen_cmd) return scen_command(scen, std::cout);
        if (*pareto_cmd) return pareto_command(pareto, std::cout);
        if (*front_cmd) return front_command(front, std::cout);
        if (*roughset_cmd) return roughset_command(roughset, std::cout);
        if (*bench_cmd) return bench_command(bench, std::cout);
        if (*report_cmd) return report_command(report, std::cout);
        if (*export_cmd) return export_command(exporting, std::cout);
        if (*import_cmd) return import_command(importing, std::cout);
        if (*merge_cmd) {
            const auto s = pride::storage::merge_stores(merge_inputs, merge_out);
            std::cout << fmt::format(
                "merged {} stores into {}: {} runs ({} found in more than one store, equal, kept "
                "once)\n",
                merge_inputs.size(), merge_out, s.runs, s.shared);
            return 0;
        }
        return 2;
    } catch (const CLI::Success& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        pride::cli::print_stderr("pride: {}\n", printable(e.what()));
        error_printed = true;
        return 2;
    } catch (const pride::InputError& e) {
        pride::cli::print_stderr("pride: {}\n", user_message(e));
        error_printed = true;
        return 2;
    } catch (const std::exception& e) {
        pride::cli::print_stderr("pride: internal error: {}\n", printable(e.what()));
        error_printed = true;
        return 1;
    }
}
