#include "engine/campaign.hpp"

#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "engine/json.hpp"
#include "engine/store.hpp"
#include "framework/error.hpp"

#ifdef PRIDE_HAVE_MPI
#include <mpi.h>
#endif

namespace pride::engine {
namespace {

std::string where_of(const Campaign& c, int line, const std::string& what) {
    if (!c.file.empty() && line > 0) return fmt::format("{}:{}", c.file, line);
    return (c.file.empty() ? std::string("campaign") : c.file) + ": " + what;
}

/// A canonical text of a campaign built in code, so that a store is never mixed with another's.
std::string describe(const Campaign& c) {
    std::string s = fmt::format("name = {}\nseeds = {}\n", json_string(c.name), c.seeds);
    if (c.budget.evaluations) s += fmt::format("evaluations = {}\n", *c.budget.evaluations);
    if (c.budget.iterations) s += fmt::format("iterations = {}\n", *c.budget.iterations);
    if (c.target) s += fmt::format("target = {}\n", json_number(*c.target));
    for (const auto& p : c.problems) {
        s += "problem " + json_string(p.id) + ": ";
        if (const auto* f = std::get_if<ContinuousSpec>(&p.spec)) {
            s += fmt::format("{} {}", f->function, f->dim);
            if (f->instance) s += fmt::format(" instance {}", *f->instance);  // absent: texts as before instances
        }
        if (const auto* g = std::get_if<GridSpec>(&p.spec))
            s += fmt::format("grid {} {} ({},{}) ({},{}) {} {} {} {} {} {} {}", json_string(p.map_file), p.inflate,
                             g->start.x, g->start.y, g->goal.x, g->goal.y, g->objective, g->encoding, g->connector,
                             g->waypoints, g->init, g->corner_cutting, json_array(g->weights));
        if (const auto* g = std::get_if<GridSpec>(&p.spec); g && g->lambda) s += " lambda " + json_number(*g->lambda);
        s += "\n";
    }
    for (const auto& a : c.algorithms) {
        s += "algorithm " + json_string(a.id) + ": " + a.spec.name;
        for (const auto& [k, v] : a.spec.params.values()) s += " " + k + "=" + json_number(v);
        s += "\n";
    }
    return s;
}

struct Task {
    const CampaignProblem* problem;
    const CampaignAlgorithm* algorithm;
    std::int64_t seed;
};

/// Every (problem, algorithm, seed) of the campaign, in a fixed order that every process shares.
std::vector<Task> all_tasks(const Campaign& c) {
    std::vector<Task> tasks;
    for (const auto& p : c.problems)
        for (const auto& a : c.algorithms)
            for (std::int64_t seed = 1; seed <= c.seeds; ++seed) tasks.push_back({&p, &a, seed});
    return tasks;
}

#ifdef PRIDE_HAVE_MPI
// Runs spread over MPI ranks: rank 0 owns the store and hands out task numbers; the other ranks
// run them and send the records back. Values equal those of a threaded run: a run depends only
// on its task.
constexpr int kTagResult = 1, kTagTask = 2;
constexpr char kSep = '\x1f';

std::string serialise(const RunRecord& r) {
    return fmt::format("{1}{0}{2}{0}{3}{0}{4}{0}{5:.17g}{0}{6}{0}{7}{0}{8:.17g}{0}{9}{0}{10}{0}{11}{0}{12}{0}{13}",
                       kSep, r.problem, r.algorithm, r.seed, r.feasible ? 1 : 0, r.best, r.evaluations, r.iterations,
                       r.wall_ms, r.optimum ? fmt::format("{:.17g}", *r.optimum) : "", r.solution, r.history,
                       r.history_evaluations, r.target_hits);
}

RunRecord deserialise(const std::string& text) {
    std::vector<std::string> f;
    for (std::size_t start = 0;;) {
        const std::size_t end = text.find(kSep, start);
        f.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    if (f.size() != 13) throw std::runtime_error("MPI: a malformed run record");
    RunRecord r;
    r.problem = f[0];
    r.algorithm = f[1];
    r.seed = std::stoll(f[2]);
    r.feasible = f[3] == "1";
    r.best = std::stod(f[4]);
    r.evaluations = std::stoll(f[5]);
    r.iterations = std::stoll(f[6]);
    r.wall_ms = std::stod(f[7]);
    if (!f[8].empty()) r.optimum = std::stod(f[8]);
    r.solution = f[9];
    r.history = f[10];
    r.history_evaluations = f[11];
    r.target_hits = f[12];
    return r;
}

BenchSummary bench_mpi(const Campaign& c, const std::string& store_path, int rank, int size) {
    const std::vector<Task> tasks = all_tasks(c);
    if (rank != 0) {
        std::string payload;  // empty: "ready"; "!..." a failure; else a record
        for (;;) {
            MPI_Send(payload.data(), static_cast<int>(payload.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
            long long index = -1;
            MPI_Recv(&index, 1, MPI_LONG_LONG, 0, kTagTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (index < 0) return {};
            try {
                const Task& t = tasks[static_cast<std::size_t>(index)];
                payload = serialise(run_one(*t.problem, *t.algorithm, c.budget, t.seed));
            } catch (const std::exception& e) {
                payload = std::string("!") + e.what();
            }
        }
    }
    std::exception_ptr failure;
    std::vector<long long> pending;
    std::size_t already = 0, stored = 0;
    std::optional<Store> store;
    try {
        store.emplace(store_path);
        store->claim(c);
        const auto done = store->done();
        already = done.size();
        for (std::size_t i = tasks.size(); i-- > 0;)
            if (!done.count({tasks[i].problem->id, tasks[i].algorithm->id, tasks[i].seed}))
                pending.push_back(static_cast<long long>(i));  // taken from the back: in task order
    } catch (...) {
        failure = std::current_exception();
    }
    for (int active = size - 1; active > 0;) {
        MPI_Status status;
        MPI_Probe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &status);
        int length = 0;
        MPI_Get_count(&status, MPI_CHAR, &length);
        std::string payload(static_cast<std::size_t>(length), '\0');
        MPI_Recv(payload.data(), length, MPI_CHAR, status.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (!payload.empty() && !failure) {
            try {
                if (payload.front() == '!') throw InputError(payload.substr(1));
                store->insert(deserialise(payload));
                ++stored;
            } catch (...) {
                failure = std::current_exception();
            }
        }
        long long next = -1;
        if (!failure && !pending.empty()) {
            next = pending.back();
            pending.pop_back();
        }
        MPI_Send(&next, 1, MPI_LONG_LONG, status.MPI_SOURCE, kTagTask, MPI_COMM_WORLD);
        if (next < 0) --active;
    }
    if (failure) std::rethrow_exception(failure);
    return {stored, already, tasks.size(), size};
}
#endif

}  // namespace

void prepare(Campaign& c) {
    const std::string file = c.file.empty() ? std::string("campaign") : c.file;
    require(!c.name.empty(), file, "missing key 'name'");
    require(c.seeds >= 1, file, "missing key 'seeds'");
    require(c.budget.evaluations || c.budget.iterations, file, "missing [budget] with 'evaluations' or 'iterations'");
    require(!c.problems.empty(), file, "no [[problem]]");
    require(!c.algorithms.empty(), file, "no [[algorithm]]");
    // The list of runs is made before any starts: a task and a stored key per run.
    const double runs = static_cast<double>(c.problems.size()) * static_cast<double>(c.algorithms.size()) *
                        static_cast<double>(c.seeds);
    require(runs * 128.0 <= available_memory(), file,
            fmt::format("{} runs ({} problems x {} algorithms x {} seeds) need about {} of memory to list, more "
                        "than the {} this machine has",
                        runs, c.problems.size(), c.algorithms.size(), c.seeds, format_bytes(runs * 128.0),
                        format_bytes(available_memory())));
    std::set<std::string> ids;
    for (const auto& p : c.problems)
        if (!ids.insert(p.id).second)
            throw InputError(where_of(c, p.line, "problem '" + p.id + "'"), "duplicate problem id '" + p.id + "'");
    ids.clear();
    for (const auto& a : c.algorithms)
        if (!ids.insert(a.id).second)
            throw InputError(where_of(c, a.line, "algorithm '" + a.id + "'"), "duplicate algorithm id '" + a.id + "'");

    // Each map is read once, whatever number of problems use it.
    std::map<std::pair<std::string, std::int64_t>, std::shared_ptr<const grid::GridMap>> maps;
    for (auto& p : c.problems) {
        const std::string where = where_of(c, p.line, "problem '" + p.id + "'");
        try {
            if (auto* g = std::get_if<GridSpec>(&p.spec)) {
                check_grid_names(*g);
                if (!g->map) {
                    auto& m = maps[{p.map_file, p.inflate}];
                    if (!m) m = load_map(p.map_file, p.inflate);
                    g->map = m;
                }
                // The exact optimum beside every run whose objective has one, for gaps in reports.
                g->oracle = false;
                Problem problem(p.spec);
                if (problem.has_optimum()) {
                    problem = problem.with_oracle();
                    g->oracle = true;
                }
                p.problem = std::make_shared<const Problem>(std::move(problem));
            } else {
                p.problem = std::make_shared<const Problem>(p.spec);
            }
        } catch (const InputError& e) {
            throw InputError(where, "problem '" + p.id + "': " + e.what());
        }
    }
    for (const auto& a : c.algorithms) {
        const std::string where = where_of(c, a.line, "algorithm '" + a.id + "'");
        for (const auto& p : c.problems) {
            try {
                check(a.spec, *p.problem, c.budget);
            } catch (const InputError& e) {
                throw InputError(where, "algorithm '" + a.id + "' on problem '" + p.id + "': " + e.what());
            }
        }
    }
    if (c.text.empty()) c.text = describe(c);
}

RunRecord run_one(const CampaignProblem& p, const CampaignAlgorithm& a, const Budget& budget, std::int64_t seed) {
    RunRecord r;
    r.problem = p.id;
    r.algorithm = a.id;
    r.seed = seed;
    const std::optional<double> optimum = p.problem->optimum_value();
    Budget with_targets = budget;
    if (optimum)
        for (const double precision : coco_precisions()) with_targets.recorded_targets.push_back(*optimum + precision);
    const RunResult result = run(a.spec, *p.problem, with_targets, static_cast<std::uint64_t>(seed));
    if (result.grid) {
        r.feasible = result.grid->feasible;
        r.best = r.feasible ? result.grid->value : std::numeric_limits<double>::infinity();
        r.optimum = result.grid->optimum;
        r.solution = json_cells(result.grid->path);
    } else {
        r.best = result.best_f;
        r.feasible = std::isfinite(result.best_f);
        r.solution = json_array(result.best_x);
    }
    r.evaluations = result.evaluations;
    r.iterations = result.iterations;
    r.wall_ms = result.wall_ms;
    r.history = json_array(result.history);
    r.history_evaluations = json_integers(result.history_evaluations);
    if (optimum) {
        r.target_hits = "[";
        for (std::size_t k = 0; k < coco_precisions().size(); ++k)
            r.target_hits += (k ? ", " : "") + (k < result.target_hits.size() ? std::to_string(result.target_hits[k])
                                                                              : std::string("null"));
        r.target_hits += "]";
    }
    return r;
}

int launched_ranks() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
        if (const char* v = std::getenv(name)) return std::max(1, std::atoi(v));
    return 1;
}

BenchSummary run_campaign(const Campaign& c, const std::string& store_path, std::int64_t jobs,
                          const Progress& progress) {
#ifdef PRIDE_HAVE_MPI
    if (launched_ranks() > 1) {  // MPI only under mpirun: a plain run needs no MPI runtime
        int initialised = 0;
        MPI_Initialized(&initialised);
        if (!initialised) MPI_Init(nullptr, nullptr);
        struct Finalise {
            ~Finalise() {
                int finalised = 0;
                MPI_Finalized(&finalised);
                if (!finalised) MPI_Finalize();
            }
        } finalise;
        int rank = 0, size = 1;
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        MPI_Comm_size(MPI_COMM_WORLD, &size);
        if (size > 1) return bench_mpi(c, store_path, rank, size);
    }
#else
    require(launched_ranks() == 1, "pride bench",
            "this pride was built without MPI, so under mpirun every rank would run the whole campaign; install "
            "Open MPI (bash scripts/deps.sh) and rebuild with `cmake -S . -B build -DPRIDE_MPI=ON && cmake "
            "--build build` (a build configured before Open MPI was installed keeps PRIDE_MPI off until told)");
#endif
    require(jobs >= 1 && jobs <= 1024, "jobs", "must be in [1, 1024], got " + std::to_string(jobs));
    Store store(store_path);
    store.claim(c);
    const auto done = store.done();

    std::vector<Task> tasks = all_tasks(c);
    const std::size_t total = tasks.size();
    std::erase_if(tasks, [&](const Task& t) { return done.count({t.problem->id, t.algorithm->id, t.seed}) != 0; });

    std::mutex mutex;
    std::condition_variable ready;
    std::deque<RunRecord> finished;
    std::exception_ptr failure;
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    auto worker = [&] {
        for (std::size_t i; !stop && (i = next++) < tasks.size();) {
            try {
                RunRecord r = run_one(*tasks[i].problem, *tasks[i].algorithm, c.budget, tasks[i].seed);
                const std::lock_guard lock(mutex);
                finished.push_back(std::move(r));
            } catch (...) {
                const std::lock_guard lock(mutex);
                if (!failure) failure = std::current_exception();
                stop = true;
            }
            ready.notify_one();
        }
    };
    std::vector<std::thread> pool;
    for (std::int64_t j = 0; j < std::min<std::int64_t>(jobs, static_cast<std::int64_t>(tasks.size())); ++j)
        pool.emplace_back(worker);

    const auto start = std::chrono::steady_clock::now();
    std::size_t stored = 0;
    try {
        while (stored < tasks.size()) {
            std::unique_lock lock(mutex);
            ready.wait(lock, [&] { return !finished.empty() || failure; });
            if (failure && finished.empty()) break;
            RunRecord r = std::move(finished.front());
            finished.pop_front();
            lock.unlock();
            store.insert(r);  // the storing thread alone writes: one transaction per run
            ++stored;
            if (progress)
                progress(done.size() + stored, total,
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
    } catch (...) {
        stop = true;
        for (auto& t : pool) t.join();
        throw;
    }
    stop = true;
    for (auto& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
    return {stored, done.size(), total, 1};
}

}  // namespace pride::engine
