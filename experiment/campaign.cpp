#include "experiment/campaign.hpp"

#include <fmt/format.h>

#include <atomic>
#include <cctype>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <exception>
#include <filesystem>
#include <list>
#include <map>
#include <mutex>
#include <set>
#include <thread>
#include <tuple>

#include "engine/json.hpp"
#include "experiment/storage/digest.hpp"
#include "experiment/storage/file_name.hpp"
#include "experiment/store.hpp"
#include "framework/error.hpp"
#include "problems/continuous/catalog.hpp"
#include "problems/continuous/cec/functions.hpp"
#include "problems/continuous/cec/suites.hpp"

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
    if (c.evaluations_per_dim) s += fmt::format("evaluations_per_dim = {}\n", *c.evaluations_per_dim);
    if (c.target) s += fmt::format("target = {}\n", json_number(*c.target));
    if (c.target_precision) s += fmt::format("precision = {}\n", json_number(*c.target_precision));
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
        if (p.unknown_free) s += " unknown_free";
        if (p.path_gaps) s += " path_gaps";
        if (const auto* g = std::get_if<GridSpec>(&p.spec); g && g->lambda) s += " lambda " + json_number(*g->lambda);
        s += "\n";
    }
    for (const auto& a : c.algorithms) {
        s += "algorithm " + json_string(a.id) + ": " + a.spec.name;
        for (const auto& [k, v] : a.spec.params.values()) s += " " + k + "=" + json_number(v);
        for (const auto& [k, v] : a.spec.params.names()) s += " " + k + "=" + json_string(v);
        s += "\n";
    }
    return s;
}

}  // namespace

std::string budget_definition(const Campaign& c) {
    std::string s;
    if (c.budget.evaluations) s += fmt::format("evaluations = {}; ", *c.budget.evaluations);
    if (c.evaluations_per_dim) s += fmt::format("evaluations_per_dim = {}; ", *c.evaluations_per_dim);
    if (c.budget.iterations) s += fmt::format("iterations = {}; ", *c.budget.iterations);
    // No evaluation budget given: the CEC problems run their suites' MaxFES (prepare()).
    if (!c.budget.evaluations && !c.evaluations_per_dim &&
        std::any_of(c.problems.begin(), c.problems.end(), [](const CampaignProblem& p) { return p.evaluations; }))
        s += "evaluations by the CEC suites' rules; ";
    return s.empty() ? s : s.substr(0, s.size() - 2);
}

std::string problem_definition(const CampaignProblem& p) {
    if (p.is_multiobjective()) {
        const auto* f = std::get_if<ContinuousSpec>(&p.spec);
        CampaignProblem plain = p;
        plain.objectives.reset();
        const std::string objectives = p.objectives->empty() ? "(default)" : *p.objectives;
        return f ? fmt::format("{} dim {} objectives {}", f->function,
                               f->dim == 0 ? std::string("(default)") : std::to_string(f->dim), objectives)
                 : problem_definition(plain) + " objectives " + objectives;
    }
    if (const auto* f = std::get_if<ContinuousSpec>(&p.spec))
        return fmt::format("{} dim {} instance {}", f->function, f->dim,
                           p.problem ? p.problem->instance() : f->instance.value_or(0));
    if (const auto* g = std::get_if<GridSpec>(&p.spec)) {
        const std::string map =
            p.map_file.empty() ? std::string("(a map given in code)") : std::filesystem::absolute(p.map_file).string();
        std::string s = fmt::format(
            "grid {} inflate {} start ({},{}) goal ({},{}) objective {} encoding {} connector {} waypoints {} init {} "
            "corner_cutting {} weights {}",
            json_string(map), p.inflate, g->start.x, g->start.y, g->goal.x, g->goal.y, g->objective,
            g->encoding.empty() ? "(native)" : g->encoding, g->connector, g->waypoints,
            g->init.empty() ? "(default)" : g->init, g->corner_cutting, json_array(g->weights));
        if (g->lambda) s += " lambda " + json_number(*g->lambda);
        // Only when set, so that the definitions of earlier stores stay as they were written.
        if (p.unknown_free) s += " unknown_free true";
        if (p.path_gaps) s += " path_gaps true";  // what its runs record (only when set, as above)
        return s;
    }
    return "function (a callback: known by its id alone)";
}

namespace {

std::string map_digest(const grid::GridMap& m) {
    storage::Sha256 h;
    h.field("grid map v1");
    const std::int64_t size[2] = {m.width(), m.height()};
    h.add(size, sizeof size);
    unsigned char chunk[4096];
    std::size_t used = 0;
    for (std::size_t i = 0; i < m.size(); ++i) {
        chunk[used++] = m.free_index(i) ? 0 : 1;
        if (used == sizeof chunk) {
            h.add(chunk, used);
            used = 0;
        }
    }
    h.add(chunk, used);
    return h.hex();
}

std::string settings_digest(const CampaignProblem& p) {
    storage::Sha256 h;
    const auto number = [&](double v) { h.field(json_number(v)); };
    if (p.is_multiobjective()) h.field("objectives v1").field(*p.objectives);
    if (const auto* f = std::get_if<ContinuousSpec>(&p.spec)) {
        h.field("function v1").field(f->function).field(std::to_string(f->dim));
        h.field(std::to_string(p.problem ? p.problem->instance() : f->instance.value_or(0)));
        // A CEC function is also its data, which the user names (PRIDE_CEC2017_DATA): another folder
        // or an edited file makes another problem.
        const auto* item = continuous::catalog().find(f->function);
        if (item && item->entry.suite.starts_with("cec"))
            h.field(fmt::format("cec data {:016x}", continuous::cec::data_fingerprint(
                                                        item->entry.suite == "cec2017" ? continuous::cec::Suite::y2017
                                                                                       : continuous::cec::Suite::y2022,
                                                        item->entry.number, static_cast<std::size_t>(f->dim))));
    } else if (const auto* g = std::get_if<GridSpec>(&p.spec)) {
        h.field("grid v1").field(std::to_string(p.inflate));
        if (p.unknown_free) h.field("unknown cells free");  // only when set: earlier digests unchanged
        h.field(fmt::format("{},{} {},{}", g->start.x, g->start.y, g->goal.x, g->goal.y));
        h.field(g->objective).field(g->encoding).field(g->connector).field(std::to_string(g->waypoints));
        h.field(g->init).field(g->corner_cutting ? "corner cutting" : "no corner cutting");
        h.field(std::to_string(g->weights.size()));
        for (const double w : g->weights) number(w);
        h.field(g->lambda ? json_number(*g->lambda) : "no lambda");
        // A Python objective is known only as being one (and whether it has its per-step form).
        h.field(!g->path_objective             ? "no user objective"
                : g->path_objective->step_cost ? "a user objective with step costs"
                                               : "a user objective");
    } else if (const auto* b = std::get_if<CallbackSpec>(&p.spec)) {
        h.field("callback v1").field(b->name).field(std::to_string(b->lower.size()));
        for (const double v : b->lower) number(v);
        for (const double v : b->upper) number(v);
        h.field(b->f_opt ? json_number(*b->f_opt) : "no f_opt");
    }
    return h.hex();
}

/// The part of a digest after "LABEL sha256:", or empty.
std::string digest_part(const std::string& digest, const std::string& label) {
    const std::string key = label + " sha256:";
    const auto at = digest.find(key);
    return at == std::string::npos ? std::string() : digest.substr(at + key.size(), 64);
}

std::string compose_digest(const std::string& map_hex, const CampaignProblem& p) {
    return (map_hex.empty() ? std::string() : "map sha256:" + map_hex + "; ") + "settings sha256:" + settings_digest(p);
}

}  // namespace

std::string problem_digest(const CampaignProblem& p) {
    const auto* g = std::get_if<GridSpec>(&p.spec);
    return compose_digest(g && g->map ? map_digest(*g->map) : std::string(), p);
}

MoProblemSpec multiobjective_spec(const CampaignProblem& p) {
    if (const auto* g = std::get_if<GridSpec>(&p.spec)) {
        MoGridSpec s;
        s.grid = *g;
        s.objectives = *p.objectives;
        return s;
    }
    const auto& f = std::get<ContinuousSpec>(p.spec);
    MoBenchmarkSpec s{f.function, f.dim, 0};
    if (!p.objectives->empty()) {
        const std::string& m = *p.objectives;
        require(m.find_first_not_of("0123456789") == std::string::npos && m.size() <= 6, "objectives",
                "expected the number of objectives M, got '" + m + "'");
        s.objectives = std::stoll(m);
    }
    return s;
}

std::string digest_difference(const std::string& stored, const std::string& now) {
    const auto shown = [](const std::string& hex) { return hex.empty() ? std::string("none") : hex.substr(0, 16); };
    for (const char* part : {"map", "settings"}) {
        const std::string a = digest_part(stored, part), b = digest_part(now, part);
        if (a != b)
            return fmt::format("has {} than the stored one{} ({}; sha256 {}... stored, {}... now)",
                               part == std::string("map") ? "another map" : "other settings",
                               part == std::string("map") ? "" : "s",
                               part == std::string("map") ? "its cells or size differ: the map was edited, or another "
                                                            "map given"
                                                          : "its start, goal, objective, weights, bounds or another "
                                                            "setting differ",
                               shown(a), shown(b));
    }
    return "differs from the stored one (" + stored + " stored, " + now + " now)";
}

std::string name_problem(const std::string& name) {
    if (name.empty()) return "must not be empty";
    // Reports and exports name files and folders after ids, a figure after a problem and an
    // algorithm together: two ids of 100 bytes and their suffixes stay within the 255 bytes of a
    // file name, so that a stored run can always be reported.
    if (name.size() > kMaxNameBytes)
        return fmt::format("must be at most {} bytes long (it has {}): reports and exports name files after it",
                           kMaxNameBytes, name.size());
    for (std::size_t i = 0; i < name.size(); ++i) {
        const auto u = static_cast<unsigned char>(name[i]);
        // C0 controls and DEL, and C1 controls (U+0080-U+009F, two bytes in UTF-8): a terminal
        // acts on them (ESC starts a control sequence) rather than showing them.
        const bool c1 = u == 0xc2 && i + 1 < name.size() && static_cast<unsigned char>(name[i + 1]) >= 0x80 &&
                        static_cast<unsigned char>(name[i + 1]) <= 0x9f;
        if (u == 0) return fmt::format("must not contain a NUL character (U+0000 at byte {})", i + 1);
        if (u < 0x20 || u == 0x7f || c1)
            return fmt::format("must not contain control characters (U+{:04X} at byte {})",
                               c1 ? static_cast<unsigned char>(name[i + 1]) : u, i + 1);
    }
    return "";
}

double problem_memory(const ProblemSpec& spec) {
    constexpr double built = 16e3;
    if (const auto* f = std::get_if<ContinuousSpec>(&spec)) {
        const auto* item = continuous::catalog().find(f->function);
        const double n = std::max(0.0, static_cast<double>(f->dim));
        const bool rotated = item && f->instance.value_or(continuous::default_instance(item->entry)) != 0 &&
                             item->entry.instances != continuous::Instances::none;
        return built + 8.0 * (8.0 * n + (rotated ? 2.0 * n * n : 0.0));
    }
    return built;
}

double run_list_memory(std::size_t problem_id_length, std::size_t algorithm_id_length) {
    // A task (24 bytes), its number (8), its key (72) and the key's node in the set of stored
    // keys (72 + 48), each key's ids on the heap beyond 15 characters (with malloc's overhead).
    const auto heap = [](std::size_t n) { return n > 15 ? 2.0 * (static_cast<double>(n) + 32.0) : 0.0; };
    return 224.0 + heap(problem_id_length) + heap(algorithm_id_length);
}

std::string algorithm_definition(const CampaignAlgorithm& a) {
    std::string s = a.spec.name;
    for (const auto& [k, v] : a.spec.params.values()) s += " " + k + "=" + json_number(v);
    for (const auto& [k, v] : a.spec.params.names()) s += " " + k + "=" + json_string(v);
    return s;
}

namespace {

/// The budget of one problem's runs: the campaign's, with its evaluations per dimension resolved.
Budget budget_of(const Budget& budget, const CampaignProblem& p) {
    Budget b = budget;
    if (p.evaluations) b.evaluations = p.evaluations;
    return b;
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
    return fmt::format(
        "{1}{0}{2}{0}{3}{0}{4}{0}{5:.17g}{0}{6}{0}{7}{0}{8:.17g}{0}{9}{0}{10}{0}{11}{0}{12}{0}{13}{0}{14}{0}{15}{0}{"
        "16}{0}{17}{0}{18}{0}{19}{0}{20}",
        kSep, r.problem, r.algorithm, r.seed, r.feasible ? 1 : 0, r.best, r.evaluations, r.iterations, r.wall_ms,
        r.optimum ? fmt::format("{:.17g}", *r.optimum) : "", r.solution, r.history, r.history_evaluations,
        r.target_hits, r.encoding, r.trace_targets, r.trace_evaluations,
        r.max_evaluations ? std::to_string(*r.max_evaluations) : "", r.checkpoints, r.path_metrics, r.polyline);
}

RunRecord deserialise(const std::string& text) {
    std::vector<std::string> f;
    for (std::size_t start = 0;;) {
        const std::size_t end = text.find(kSep, start);
        f.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    if (f.size() != 20) throw std::runtime_error("MPI: a malformed run record");
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
    r.encoding = f[13];
    r.trace_targets = f[14];
    r.trace_evaluations = f[15];
    if (!f[16].empty()) r.max_evaluations = std::stoll(f[16]);
    r.checkpoints = f[17];
    r.path_metrics = f[18];
    r.polyline = f[19];
    return r;
}

#endif

/// The process that owns the store: the runs still to take (claimed from the store in batches,
/// so that other processes on the same store take others), and the commits of finished ones.
class Ledger {
  public:
    Ledger(const Campaign& c, const std::string& path, std::size_t batch)
        : tasks_(all_tasks(c)), budget_(c.budget), batch_(std::max<std::size_t>(batch, 1)) {
        store_.emplace(path);
        store_->claim(c);
        // The campaign's runs the store holds (a grown store may hold runs of other seeds,
        // problems or algorithms too: they stay, and are not this campaign's).
        const auto done = store_->done();
        for (std::size_t i = 0; i < tasks_.size(); ++i) {
            RunKey key{tasks_[i].problem->id, tasks_[i].algorithm->id, tasks_[i].seed};
            if (done.count(key)) {
                ++already_;
                continue;
            }
            todo_.push_back(i);
            keys_.push_back(std::move(key));
        }
    }

    const std::vector<Task>& tasks() const { return tasks_; }
    const Budget& budget() const { return budget_; }
    std::size_t todo() const { return todo_.size(); }
    std::size_t in_store() const { return already_ + stored_; }

    /// The next runs to do (task numbers), claimed in the store; empty when none is left that
    /// no live process holds.
    std::vector<std::size_t> take() {
        try {
            return take_from_store();
        } catch (const InputError& e) {
            throw with_count(e);
        }
    }

    void commit(const std::vector<RunRecord>& records) {
        try {
            stored_ += store_->insert(records);
        } catch (const InputError& e) {
            throw with_count(e);
        }
    }

  private:
    /// A store error with what the store holds and how to go on.
    InputError with_count(const InputError& e) const {
        return InputError(fmt::format("{} ({} runs are stored and kept; run the same command again to resume)",
                                      e.what(), in_store()));
    }

    std::vector<std::size_t> take_from_store() {
        for (;;) {
            std::vector<std::size_t> out;
            for (const std::size_t at : store_->take(keys_, cursor_, batch_, busy_)) out.push_back(todo_[at]);
            if (!out.empty() || cursor_ < keys_.size()) return out;
            // Everything looked at: the runs other processes hold are retried once such a
            // process has died (its claims dropped).
            if (busy_.empty() || !store_->drop_dead_claims()) return out;
            std::vector<std::size_t> todo;
            std::vector<RunKey> keys;
            for (const std::size_t at : busy_) {
                todo.push_back(todo_[at]);
                keys.push_back(keys_[at]);
            }
            todo_ = std::move(todo);
            keys_ = std::move(keys);
            busy_.clear();
            cursor_ = 0;
        }
    }

  public:
    /// The summary once every run is done; throws when the store's file went away meanwhile.
    BenchSummary finish() {
        store_->check_same_file();
        const std::size_t now = store_->count();
        const std::size_t others = now < tasks_.size() ? tasks_.size() - now : 0;
        return {stored_, already_, tasks_.size(), others, 1};
    }

    /// Drops the claims of the runs not finished, and closes the store.
    void close() { store_.reset(); }

  private:
    std::vector<Task> tasks_;
    Budget budget_;
    std::optional<Store> store_;
    std::size_t batch_;
    std::size_t already_ = 0, stored_ = 0;
    std::vector<std::size_t> todo_;  // task numbers not stored when this process started
    std::vector<RunKey> keys_;       // their keys
    std::size_t cursor_ = 0;         // keys_[cursor_...] not looked at yet
    std::vector<std::size_t> busy_;  // positions in keys_ another process held
};

#ifdef PRIDE_HAVE_MPI
/// Runs asked for per thread of a rank other than 0, at first: with two a thread finds its next
/// run waiting instead of idling for a message round trip.
constexpr std::int64_t kSlotsPerThread = 2;
/// At most this many per thread: a rank whose threads still run dry (runs shorter than a round
/// trip, which is up to two 1 ms polls) asks for one more run each time, up to here.
constexpr std::int64_t kMaxSlotsPerThread = 32;

/// A rank other than 0: `jobs` threads fed by slots, each slot asking rank 0 for a run and sending
/// back its record (which asks for the next) until rank 0 answers "no more" (-1). A thread that
/// finds no run waiting, after its first, adds a slot. Only this thread calls MPI.
void mpi_worker(const Campaign& c, std::int64_t jobs) {
    const std::vector<Task> tasks = all_tasks(c);
    std::mutex mutex;
    std::condition_variable to_workers, to_main;
    std::deque<long long> work;
    std::deque<std::string> results;  // "!..." a failure; else a record
    std::int64_t ran_dry = 0;         // times a thread, after its first run, found no run waiting
    bool done = false;
    auto worker = [&] {
        for (bool first = true;; first = false) {
            long long index = -1;
            {
                std::unique_lock lock(mutex);
                if (work.empty() && !done && !first) {
                    ++ran_dry;
                    to_main.notify_one();
                }
                to_workers.wait(lock, [&] { return done || !work.empty(); });
                if (work.empty()) return;
                index = work.front();
                work.pop_front();
            }
            std::string payload;
            try {
                const Task& t = tasks[static_cast<std::size_t>(index)];
                payload = serialise(run_one(*t.problem, *t.algorithm, c.budget, t.seed));
            } catch (const std::exception& e) {
                payload = std::string("!") + e.what();
            }
            {
                const std::lock_guard lock(mutex);
                results.push_back(std::move(payload));
            }
            to_main.notify_one();
        }
    };
    std::vector<std::thread> pool;
    for (std::int64_t j = 0; j < jobs; ++j) pool.emplace_back(worker);
    std::list<std::string> sending;               // records being sent, in order
    std::vector<MPI_Request> requests;            // their sends
    std::int64_t slots = jobs * kSlotsPerThread;  // asked for so far
    std::int64_t open = 0;                        // slots that have not been told "no more"
    bool finishing = false;                       // rank 0 has said "no more" to a slot
    const auto ask = [&] {
        MPI_Send(nullptr, 0, MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
        ++open;
    };
    for (std::int64_t j = 0; j < slots; ++j) ask();
    while (open > 0) {
        for (int flag = 1; flag;) {
            MPI_Iprobe(0, kTagTask, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE);
            if (!flag) break;
            long long index = -1;
            MPI_Recv(&index, 1, MPI_LONG_LONG, 0, kTagTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (index < 0) {
                --open;
                if (!finishing) {  // no slot is added after this, as rank 0 learns from it
                    MPI_Send("#", 1, MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
                    finishing = true;
                }
                continue;
            }
            {
                const std::lock_guard lock(mutex);
                work.push_back(index);
            }
            to_workers.notify_one();
        }
        std::deque<std::string> ready;
        std::int64_t dry = 0;
        {
            std::unique_lock lock(mutex);
            to_main.wait_for(lock, std::chrono::milliseconds(1), [&] { return !results.empty() || ran_dry > 0; });
            ready.swap(results);
            std::swap(dry, ran_dry);
        }
        for (; dry > 0 && !finishing && slots < jobs * kMaxSlotsPerThread; --dry, ++slots) ask();
        // Non-blocking: a record over Open MPI's eager limit (a few KB) waits for rank 0 to take it,
        // and a blocking send spent that wait polling, on a core the runs need. The payloads stay
        // alive (a list: no moves) until their sends complete.
        for (auto& payload : ready) {
            sending.push_back(std::move(payload));
            requests.emplace_back();
            MPI_Isend(sending.back().data(), static_cast<int>(sending.back().size()), MPI_CHAR, 0, kTagResult,
                      MPI_COMM_WORLD, &requests.back());
        }
        while (!requests.empty()) {  // the finished sends, oldest first
            int complete = 0;
            MPI_Test(&requests.front(), &complete, MPI_STATUS_IGNORE);
            if (!complete) break;
            requests.erase(requests.begin());
            sending.pop_front();
        }
    }
    if (!requests.empty()) MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
    {
        const std::lock_guard lock(mutex);
        done = true;
    }
    to_workers.notify_all();
    for (auto& t : pool) t.join();
}

/// Rank 0's view of the other ranks: each has slots; a slot asks for a run, gets one, and sends its
/// record back, which asks for the next. An empty message is a slot asking, so a rank may add
/// slots; rank 0 counts them as they arrive.
class Remotes {
  public:
    explicit Remotes(int size)
        : idle_(static_cast<std::size_t>(size), 0),
          open_(static_cast<std::size_t>(size), 0),
          closed_(static_cast<std::size_t>(size), false) {}

    /// Reads the messages waiting; the records go to `finished`, the slots asking for work to the
    /// idle counts. A failure on a rank is thrown. Receives are non-blocking: a record over the
    /// eager limit needs its sender to act, and a blocking receive would poll a core meanwhile.
    void poll(std::vector<RunRecord>& finished) {
        for (;;) {
            int flag = 0;
            MPI_Message message;
            MPI_Status status;
            MPI_Improbe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &message, &status);
            if (!flag) break;
            int length = 0;
            MPI_Get_count(&status, MPI_CHAR, &length);
            receiving_.push_back({std::string(static_cast<std::size_t>(length), '\0'), status.MPI_SOURCE});
            requests_.emplace_back();
            MPI_Imrecv(receiving_.back().payload.data(), length, MPI_CHAR, &message, &requests_.back());
        }
        while (!requests_.empty()) {  // the finished receives, oldest first
            int complete = 0;
            MPI_Test(&requests_.front(), &complete, MPI_STATUS_IGNORE);
            if (!complete) break;
            Received got = std::move(receiving_.front());
            requests_.erase(requests_.begin());
            receiving_.pop_front();
            const auto r = static_cast<std::size_t>(got.source);
            if (got.payload == "#") {  // the rank's last slot has asked already (messages keep their order)
                closed_[r] = true;
                continue;
            }
            ++idle_[r];  // a new slot asking, or a record, which frees its slot for the next run
            if (got.payload.empty()) {
                ++open_[r];
                continue;
            }
            if (got.payload.front() == '!') throw InputError(got.payload.substr(1));
            finished.push_back(deserialise(got.payload));
        }
    }
    /// The number of slots waiting for a run.
    std::size_t idle() const {
        std::size_t n = 0;
        for (const std::int64_t k : idle_) n += static_cast<std::size_t>(k);
        return n;
    }
    void give(long long task) {
        for (std::size_t r = 1; r < idle_.size(); ++r)
            if (idle_[r] > 0) {
                MPI_Send(&task, 1, MPI_LONG_LONG, static_cast<int>(r), kTagTask, MPI_COMM_WORLD);
                --idle_[r];
                return;
            }
    }
    /// Sends "no more" to every slot, waiting for the ones still running (their records dropped),
    /// until every rank has said it adds no slot ("#", sent on its first "no more") and has had
    /// "no more" for each slot it asked for.
    void release_all() {
        std::vector<RunRecord> ignored;
        for (;;) {
            for (std::size_t r = 1; r < idle_.size(); ++r)
                for (; idle_[r] > 0; --idle_[r]) {
                    const long long none = -1;
                    MPI_Send(&none, 1, MPI_LONG_LONG, static_cast<int>(r), kTagTask, MPI_COMM_WORLD);
                    --open_[r];
                }
            bool any_open = false;
            for (std::size_t r = 1; r < open_.size(); ++r) any_open = any_open || open_[r] > 0 || !closed_[r];
            if (!any_open && requests_.empty()) break;
            try {
                poll(ignored);
            } catch (...) {
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    }

  private:
    struct Received {
        std::string payload;
        int source;
    };
    std::vector<std::int64_t> idle_;  // per rank, slots waiting for a run
    std::vector<std::int64_t> open_;  // per rank, slots not yet told "no more"
    std::vector<bool> closed_;        // per rank, "#" received: it asks for no more slots
    std::list<Received> receiving_;   // receives under way, in order (a list: the buffers stay put)
    std::vector<MPI_Request> requests_;
};
#else
class Remotes {
  public:
    void poll(std::vector<RunRecord>&) {}
    std::size_t idle() const { return 0; }
    void give(long long) {}
    void release_all() {}
};
#endif

/// Runs the ledger's runs on `jobs` threads of this process (and the other MPI ranks, when
/// `remotes`), committing what finishes in batches from this thread alone, so that the commits
/// never hold up the runs.
BenchSummary run_local(Ledger& ledger, std::int64_t jobs, const Progress& progress, const Stop& stop,
                       Remotes* remotes) {
    const std::vector<Task>& tasks = ledger.tasks();
    const Budget budget = ledger.budget();
    std::mutex mutex;
    std::condition_variable to_workers, to_main;
    std::deque<std::size_t> work;  // claimed, not started
    bool no_more = false, quit = false;
    std::vector<RunRecord> finished;
    std::exception_ptr failure;
    const std::size_t width = static_cast<std::size_t>(jobs);
    // The main thread shares the cores with the runs, so the threads wake it only when it has
    // something to do: the queue below half its length, `kBatch` records waiting, the last runs
    // or a failure; else it wakes every 20 ms to commit. (Waking it per run cost 14 % more CPU at
    // --jobs 2 on runs of 1 ms: bench/campaign_scaling.toml.) The queue keeps 4 runs per thread,
    // and a thread that finds it empty lengthens it by one run per thread, up to 64: the main
    // thread is late when a commit waits for the disk (a checkpoint's syncs, 10-20 ms, idled
    // both threads of a campaign of 1 ms runs) or when other processes hold the cores.
    constexpr std::size_t kBatch = 16;
    std::size_t queue_length = 4 * width;  // guarded by `mutex`
    const std::size_t longest_queue = 64 * width;
    auto worker = [&] {
        for (bool first = true;; first = false) {
            std::size_t i = 0;
            {
                std::unique_lock lock(mutex);
                if (work.empty() && !no_more && !quit && !first)
                    queue_length = std::min(longest_queue, queue_length + width);
                to_workers.wait(lock, [&] { return quit || !work.empty() || no_more; });
                if (quit || work.empty()) return;
                i = work.front();
                work.pop_front();
                if (2 * work.size() < queue_length && !no_more) to_main.notify_one();  // the main thread claims more
            }
            bool wake = true;
            try {
                RunRecord r = run_one(*tasks[i].problem, *tasks[i].algorithm, budget, tasks[i].seed);
                const std::lock_guard lock(mutex);
                finished.push_back(std::move(r));
                wake = finished.size() >= kBatch || (no_more && work.empty());
            } catch (...) {
                const std::lock_guard lock(mutex);
                if (!failure) failure = std::current_exception();
                quit = true;
            }
            if (wake) {
                to_main.notify_one();
                to_workers.notify_all();
            }
        }
    };
    std::vector<std::thread> pool;
    for (std::size_t j = 0; j < std::min(width, ledger.todo()); ++j) pool.emplace_back(worker);
    const auto shut_down = [&] {
        {
            const std::lock_guard lock(mutex);
            quit = true;
        }
        to_workers.notify_all();
        for (auto& t : pool) t.join();
        pool.clear();
    };

    if (pool.empty() && !remotes) return ledger.finish();
    const auto start = std::chrono::steady_clock::now();
    std::size_t in_flight = 0;  // handed out (here or to a rank), not finished
    bool exhausted = false;
    std::deque<std::size_t> spare;   // claimed for the ranks, not yet given
    std::vector<RunRecord> waiting;  // finished, not yet committed
    auto oldest = std::chrono::steady_clock::now();
    try {
        for (;;) {
            std::vector<RunRecord> batch;
            if (remotes) remotes->poll(batch);
            // Keep the queue full for the threads, and a run for each idle slot of a rank.
            std::size_t queued = 0, length = 0;
            {
                const std::lock_guard lock(mutex);
                queued = work.size();
                length = queue_length;
            }
            const std::size_t wanted_here = pool.empty() ? 0 : (queued < length ? length - queued : 0);
            const std::size_t wanted_there = remotes ? remotes->idle() : 0;
            while (!exhausted && spare.size() < wanted_here + wanted_there) {
                const auto got = ledger.take();
                if (got.empty()) exhausted = true;
                spare.insert(spare.end(), got.begin(), got.end());
            }
            for (std::size_t k = 0; k < wanted_there && !spare.empty(); ++k) {
                remotes->give(static_cast<long long>(spare.front()));
                spare.pop_front();
                ++in_flight;
            }
            {
                const std::lock_guard lock(mutex);
                for (std::size_t k = 0; k < wanted_here && !spare.empty(); ++k) {
                    work.push_back(spare.front());
                    spare.pop_front();
                    ++in_flight;
                }
                if (exhausted && spare.empty()) no_more = true;
            }
            if (remotes && exhausted && spare.empty()) {
                // The last runs: a rank waiting for one takes this process's queued runs (the last
                // queued first), which the threads here would start only after their present ones.
                std::vector<std::size_t> moved;
                {
                    const std::lock_guard lock(mutex);
                    for (std::size_t k = remotes->idle(); k > 0 && !work.empty(); --k) {
                        moved.push_back(work.back());
                        work.pop_back();
                    }
                }
                for (const std::size_t task : moved) remotes->give(static_cast<long long>(task));
            }
            to_workers.notify_all();
            {
                std::unique_lock lock(mutex);
                // Ranks are polled every millisecond; threads wake this one themselves.
                to_main.wait_for(lock, remotes ? std::chrono::milliseconds(1) : std::chrono::milliseconds(20), [&] {
                    return finished.size() >= kBatch || failure || (no_more && work.empty() && !finished.empty()) ||
                           (!exhausted && 2 * work.size() < queue_length && !pool.empty());
                });
                for (auto& r : finished) batch.push_back(std::move(r));
                finished.clear();
            }
            in_flight -= batch.size();
            if (!batch.empty() && waiting.empty()) oldest = std::chrono::steady_clock::now();
            for (auto& r : batch) waiting.push_back(std::move(r));
            // A transaction per 20 ms (or per kBatch runs): short runs do not wait for one commit
            // each, the commits take a small share of the cores the runs use, and a finished run
            // is in the store within 20 ms.
            const bool last_ones = exhausted && spare.empty() && in_flight == 0;
            if (!waiting.empty() && (waiting.size() >= kBatch || last_ones ||
                                     std::chrono::steady_clock::now() - oldest >= std::chrono::milliseconds(20))) {
                ledger.commit(waiting);
                waiting.clear();
                if (progress)
                    progress(ledger.in_store(), tasks.size(),
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            }
            if (stop.signal && stop.signal->load() != 0) {
                std::vector<RunRecord> last = std::move(waiting);  // finished, not yet committed
                waiting.clear();
                {
                    const std::lock_guard lock(mutex);
                    quit = true;  // the queued runs are not started
                    for (auto& r : finished) last.push_back(std::move(r));
                    finished.clear();
                }
                ledger.commit(last);
                const Interrupted stopped(ledger.in_store(), tasks.size(), stop.signal->load());
                ledger.close();
                if (stop.on_stop) stop.on_stop(stopped);
                shut_down();
                if (remotes) remotes->release_all();
                throw stopped;
            }
            {
                const std::lock_guard lock(mutex);
                if (failure) break;
            }
            if (exhausted && spare.empty() && in_flight == 0) break;
        }
    } catch (const Interrupted&) {
        throw;
    } catch (...) {
        shut_down();
        if (remotes) remotes->release_all();
        throw;
    }
    shut_down();
    if (remotes) remotes->release_all();
    {
        // What finished before a failure is kept.
        for (auto& r : finished) waiting.push_back(std::move(r));
        ledger.commit(waiting);
    }
    if (failure) std::rethrow_exception(failure);
    return ledger.finish();
}

/// The CEC suite of a problem's function by the catalog (cec2017-fN and cec2022-fN, from a
/// [[suite]] or a [[problem]] alike), or nullptr.
const continuous::cec::SuiteRules* cec_rules_of(const ContinuousSpec& f) {
    const auto* item = continuous::catalog().find(f.function);
    return item ? continuous::cec::suite_rules(item->entry.suite) : nullptr;
}

}  // namespace

void apply_suite_rules(Campaign& c) {
    const std::string file = c.file.empty() ? std::string("campaign") : c.file;
    std::set<std::string_view> suites;
    const CampaignProblem* other = nullptr;      // the first problem of no CEC suite
    const CampaignProblem* no_budget = nullptr;  // the first problem without a default budget
    for (const auto& p : c.problems) {
        const auto* f = std::get_if<ContinuousSpec>(&p.spec);
        const continuous::cec::SuiteRules* rules = f ? cec_rules_of(*f) : nullptr;
        if (rules)
            suites.insert(rules->name);
        else if (!other)
            other = &p;
        if (!no_budget && !(rules && continuous::cec::default_evaluations(rules->name, f->dim))) no_budget = &p;
    }
    if (c.seeds < 1) {
        require(c.seeds == 0 && !other && suites.size() == 1, file,
                suites.empty() ? std::string("missing key 'seeds'")
                               : "missing key 'seeds': only a campaign of one CEC suite's problems has a default (51 "
                                 "runs for cec2017, 30 for cec2022)");
        c.seeds = continuous::cec::suite_rules(*suites.begin())->runs;
    }
    if (no_budget && !c.budget.evaluations && !c.budget.iterations && !c.evaluations_per_dim)
        throw InputError(file, suites.empty() ? std::string("missing [budget] with 'evaluations', "
                                                            "'evaluations_per_dim' or 'iterations'")
                                              : "missing [budget] with 'evaluations', 'evaluations_per_dim' or "
                                                "'iterations': only the CEC suites' problems have a default budget "
                                                "(CEC 2022's at D = 10 and 20), and problem '" +
                                                    no_budget->id + "' has none");
    // The CEC suites' MaxFES, where the campaign gives no evaluation budget.
    if (!c.budget.evaluations && !c.evaluations_per_dim)
        for (auto& p : c.problems)
            if (const auto* f = std::get_if<ContinuousSpec>(&p.spec))
                if (const continuous::cec::SuiteRules* rules = cec_rules_of(*f))
                    p.evaluations = continuous::cec::default_evaluations(rules->name, f->dim);
}

void prepare(Campaign& c) {
    const std::string file = c.file.empty() ? std::string("campaign") : c.file;
    require(!c.name.empty(), file, "missing key 'name'");
    require(!c.problems.empty() || c.seeds >= 1, file, "missing key 'seeds'");
    require(!c.problems.empty() || c.budget.evaluations || c.budget.iterations || c.evaluations_per_dim, file,
            "missing [budget] with 'evaluations', 'evaluations_per_dim' or 'iterations'");
    require(!(c.budget.evaluations && c.evaluations_per_dim), file,
            "[budget]: give evaluations or evaluations_per_dim, not both");
    require(!c.problems.empty(), file, "no [[problem]]");
    apply_suite_rules(c);
    require(!c.algorithms.empty(), file, "no [[algorithm]]");
    require(c.problems.size() <= max_campaign_problems, file,
            fmt::format("{} problems; a campaign has at most {}", c.problems.size(), max_campaign_problems));
    // Every problem is built, and the list of runs made (a task and a stored key per run), before
    // any run starts: both are checked here, before either is (128 bytes a run was less
    // than a key with its two ids takes, and the problems' own 12 kB each were not counted).
    std::size_t problem_id = 0, algorithm_id = 0;
    double built = 0.0;
    for (const auto& p : c.problems) {
        problem_id = std::max(problem_id, p.id.size());
        // A problem too large alone is refused as it is built, by the engine's check naming its
        // dimension; the sum is of the others.
        if (const double bytes = problem_memory(p.spec); bytes <= available_memory()) built += bytes;
    }
    for (const auto& a : c.algorithms) algorithm_id = std::max(algorithm_id, a.id.size());
    const double runs = static_cast<double>(c.problems.size()) * static_cast<double>(c.algorithms.size()) *
                        static_cast<double>(c.seeds);
    const double listed = runs * run_list_memory(problem_id, algorithm_id);
    require(built + listed <= available_memory(), file,
            fmt::format("{} problems and their {} runs ({} algorithms x {} seeds each) need about {} of memory "
                        "({} for the problems, {} to list the runs), more than the {} this machine has",
                        c.problems.size(), runs, c.algorithms.size(), c.seeds, format_bytes(built + listed),
                        format_bytes(built), format_bytes(listed), format_bytes(available_memory())));
    // Names as the store keeps and the summaries print them: one root for the campaign
    // files and Python; the name itself is not shown (it may hold the very character refused).
    if (const std::string why = name_problem(c.name); !why.empty()) throw InputError(file, "name " + why);
    for (const auto& p : c.problems)
        if (const std::string why = name_problem(p.id); !why.empty())
            throw InputError(where_of(c, p.line, "problem"), "problem id " + why);
    for (const auto& a : c.algorithms)
        if (const std::string why = name_problem(a.id); !why.empty())
            throw InputError(where_of(c, a.line, "algorithm"), "algorithm id " + why);
    std::set<std::string> ids;
    for (const auto& p : c.problems)
        if (!ids.insert(p.id).second)
            throw InputError(where_of(c, p.line, "problem '" + p.id + "'"), "duplicate problem id '" + p.id + "'");
    ids.clear();
    for (const auto& a : c.algorithms)
        if (!ids.insert(a.id).second)
            throw InputError(where_of(c, a.line, "algorithm '" + a.id + "'"), "duplicate algorithm id '" + a.id + "'");
    // Ids that would name the same file (figures, exports), also on a file system that ignores case.
    const auto same_file = [&](const auto& items, const char* kind) {
        std::map<std::string, std::string> seen;  // lower-case file name -> id
        for (const auto& item : items) {
            std::string name = storage::file_name(item.id);
            for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
            const auto [it, fresh] = seen.emplace(name, item.id);
            if (!fresh)
                throw InputError(where_of(c, item.line, std::string(kind) + " '" + item.id + "'"),
                                 fmt::format("{} ids '{}' and '{}' would name the same file ('{}'); rename one", kind,
                                             it->second, item.id, storage::file_name(item.id)));
        }
    };
    same_file(c.problems, "problem");
    same_file(c.algorithms, "algorithm");

    // Each map is read once, whatever number of problems use it.
    std::map<std::tuple<std::string, std::int64_t, bool>, std::shared_ptr<const grid::GridMap>> maps;
    for (auto& p : c.problems) {
        const std::string where = where_of(c, p.line, "problem '" + p.id + "'");
        try {
            if (auto* g = std::get_if<GridSpec>(&p.spec)) {
                check_grid_names(*g);
                if (!g->map) {
                    auto& m = maps[{p.map_file, p.inflate, p.unknown_free}];
                    grid::MapReadOptions read;
                    read.unknown_free = p.unknown_free;
                    if (!m) m = load_map(p.map_file, p.inflate, read);
                    g->map = m;
                }
                // The exact optimum beside every run whose objective has one, for gaps in reports.
                g->oracle = false;
                g->path_gaps = p.path_gaps;
                if (p.is_multiobjective()) {
                    p.multiobjective = std::make_shared<const MoProblem>(multiobjective_spec(p));
                } else {
                    Problem problem(p.spec);
                    if (problem.has_optimum()) {
                        problem = problem.with_oracle();
                        g->oracle = true;
                    }
                    p.problem = std::make_shared<const Problem>(std::move(problem));
                }
            } else if (p.is_multiobjective()) {
                p.multiobjective = std::make_shared<const MoProblem>(multiobjective_spec(p));
            } else {
                p.problem = std::make_shared<const Problem>(p.spec);
            }
            if (c.evaluations_per_dim) {
                require(!std::holds_alternative<GridSpec>(p.spec), "evaluations_per_dim",
                        "a grid problem has no dimension; give the campaign an absolute budget (evaluations)");
                const double n = static_cast<double>(*c.evaluations_per_dim) * static_cast<double>(p.dimension());
                require(n <= static_cast<double>(max_budget), "evaluations_per_dim",
                        fmt::format("{} x {} dimensions is more than {} evaluations", *c.evaluations_per_dim,
                                    p.dimension(), max_budget));
                p.evaluations = *c.evaluations_per_dim * static_cast<std::int64_t>(p.dimension());
            }
        } catch (const InputError& e) {
            throw InputError(where, "problem '" + p.id + "': " + e.what());
        }
    }
    // Each map hashed once, whatever number of problems use it.
    std::map<const grid::GridMap*, std::string> map_digests;
    for (auto& p : c.problems) {
        const auto* g = std::get_if<GridSpec>(&p.spec);
        if (!g || !g->map) {
            p.digest = problem_digest(p);
            continue;
        }
        auto& m = map_digests[g->map.get()];
        if (m.empty()) m = map_digest(*g->map);
        p.digest = compose_digest(m, p);
    }
    // A quality every run of a problem records must be computable before anything runs.
    for (const auto& p : c.problems) {
        if (!p.multiobjective) continue;
        try {
            check_quality(*p.multiobjective);
        } catch (const InputError& e) {
            throw InputError(where_of(c, p.line, "problem '" + p.id + "'"), e.what());
        }
    }
    for (const auto& a : c.algorithms) {
        const std::string where = where_of(c, a.line, "algorithm '" + a.id + "'");
        for (const auto& p : c.problems) {
            try {
                if (p.multiobjective)
                    check(a.spec, *p.multiobjective, budget_of(c.budget, p));
                else
                    check(a.spec, *p.problem, budget_of(c.budget, p));
            } catch (const InputError& e) {
                throw InputError(where, "algorithm '" + a.id + "' on problem '" + p.id + "': " + e.what());
            }
        }
    }
    if (c.text.empty()) c.text = describe(c);
}

namespace {
/// A trace as RunRecord keeps it: [e0, f0, e1, f1, ...], null for +inf.
std::string json_trace(const std::vector<TracePoint>& trace) {
    std::string text = "[";
    for (const auto& t : trace)
        text += fmt::format("{}{}, {}", text.size() > 1 ? ", " : "", t.evaluations, json_number(t.best));
    return text + "]";
}
}  // namespace

namespace {

/// A multi-objective run as stored: its value is the hypervolume gap 1 - HV / HV_ref (0 for a set
/// as good as the reference front; engine/multiobjective.hpp's normalisation), its solution the
/// whole front with its indicators: {"objectives": [...], "hypervolume_ratio", "igd_plus",
/// "exact_found" (grids), "front": [{"f": [...], "x": [...]} or, on grids, {"f", "legal", "path"}]}.
RunRecord run_multiobjective(const CampaignProblem& p, const CampaignAlgorithm& a, const Budget& budget,
                             std::int64_t seed, RunRecord r) {
    const MoProblem& problem = *p.multiobjective;
    const MoRunResult result = run(a.spec, problem, budget_of(budget, p), static_cast<std::uint64_t>(seed));
    const MoQuality q = quality(problem, result.f);
    const bool grid = problem.is_grid();
    std::string names;
    for (const auto& n : problem.objective_names()) names += (names.empty() ? "" : ", ") + json_string(n);
    r.solution = fmt::format(
        "{{\"objectives\": [{}], \"hypervolume_ratio\": {}, \"igd_plus\": {}, \"exact_found\": {}, \"front\": {}}}",
        names, json_number(q.hypervolume_ratio), json_number(q.igd_plus),
        q.exact_found ? std::to_string(*q.exact_found) : std::string("null"), front_json(result));
    r.best = 1.0 - q.hypervolume_ratio;
    // Feasible: a point found (on grids, a legal path).
    r.feasible = grid ? std::any_of(result.feasible.begin(), result.feasible.end(), [](char c) { return c != 0; })
                      : result.f.cols() > 0;
    r.evaluations = result.evaluations;
    r.iterations = result.iterations;
    r.wall_ms = result.wall_ms;
    // One point of history: the run's value after its last iteration.
    r.history = json_array({r.best});
    r.history_evaluations = json_integers({result.evaluations});
    if (grid) r.encoding = std::get<GridSpec>(p.spec).encoding.empty() ? "line" : std::get<GridSpec>(p.spec).encoding;
    return r;
}

}  // namespace

RunRecord run_one(const CampaignProblem& p, const CampaignAlgorithm& a, const Budget& budget, std::int64_t seed) {
    RunRecord r;
    r.problem = p.id;
    r.algorithm = a.id;
    r.seed = seed;
    if (p.multiobjective) return run_multiobjective(p, a, budget, seed, std::move(r));
    const std::optional<double> optimum = p.problem->optimum_value();
    Budget with_targets = budget_of(budget, p);
    if (optimum)
        for (const double precision : coco_precisions()) with_targets.recorded_targets.push_back(*optimum + precision);
    // A whole-map planner has no evaluation budget: its work (A*'s expansions, Theta*'s) is not
    // bounded by the campaign's, so no budget is recorded beside it.
    const AlgorithmEntry* entry = algorithms().find(a.spec.name);
    if (!entry || entry->evaluates()) r.max_evaluations = with_targets.evaluations;
    if (optimum && with_targets.evaluations)
        with_targets.recorded_evaluations = continuous::cec::recorded_evaluations(
            *with_targets.evaluations, static_cast<std::int64_t>(std::max<std::size_t>(p.problem->dimension(), 1)));
    const RunResult result = run(a.spec, *p.problem, with_targets, static_cast<std::uint64_t>(seed));
    if (result.grid) {
        r.feasible = result.grid->feasible;
        r.best = r.feasible ? result.grid->value : std::numeric_limits<double>::infinity();
        // The 8-connected optimum is no optimum of a polyline (shorter ones exist): a polyline
        // planner's run records none, so that reports compare it by its path gaps instead.
        if (!entry || !entry->plans_polylines) r.optimum = result.grid->optimum;
        r.solution = json_cells(result.grid->path);
        r.encoding = result.grid->encoding;
        if (r.feasible) {
            const auto* g = std::get_if<GridSpec>(&p.spec);
            r.path_metrics = json_path_metrics(*result.grid, g && g->path_gaps);
            if (result.grid->path.empty()) r.polyline = json_polyline(result.grid->polyline);
        }
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
    r.trace_targets = json_trace(result.trace_targets);
    r.trace_evaluations = json_trace(result.trace_evaluations);
    r.checkpoints = json_trace(result.checkpoints);
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

BenchSummary run_campaign(const Campaign& c, const std::string& store_path, std::int64_t jobs, const Progress& progress,
                          const Stop& stop) {
    require(jobs >= 1 && jobs <= 1024, "jobs", "must be in [1, 1024], got " + std::to_string(jobs));
#ifdef PRIDE_HAVE_MPI
    if (launched_ranks() > 1) {  // MPI only under mpirun: a plain run needs no MPI runtime
        int initialised = 0;
        MPI_Initialized(&initialised);
        if (!initialised) {
            // On one machine (every rank local) and with no PML chosen, Open MPI's start-up first
            // opens its cm PML, which probes network layers (PSM, PSM2) for 0.2 s before it settles
            // on ob1 over shared memory; asking for ob1 directly saves that in every rank. A PML
            // the user names (mpirun --mca pml X, or OMPI_MCA_pml) is left as it is.
            const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
            const char* world = std::getenv("OMPI_COMM_WORLD_SIZE");
            if (local && world && std::string(local) == world) ::setenv("OMPI_MCA_pml", "ob1", 0);
            int provided = 0;  // only the main thread calls MPI; the others only run
            MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
        }
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
        if (size > 1) {
            if (rank != 0) {
                mpi_worker(c, jobs);
                BenchSummary none;
                none.ranks = 0;  // a worker rank: rank 0 reports
                return none;
            }
            Remotes remotes(size);
            try {
                Ledger ledger(c, store_path, 4 * static_cast<std::size_t>(jobs) * static_cast<std::size_t>(size));
                BenchSummary s = run_local(ledger, jobs, progress, stop, &remotes);
                s.ranks = size;
                return s;
            } catch (...) {
                // A store that cannot be opened, say: the other ranks wait for runs, and
                // MPI_Finalize would wait for them. Told "no more", they finish (a second call
                // finds every rank closed).
                remotes.release_all();
                throw;
            }
        }
    }
#else
    require(launched_ranks() == 1, "pride bench",
            "this pride was built without MPI, so under mpirun every rank would run the whole campaign; install "
            "Open MPI (bash scripts/deps.sh) and rebuild with `cmake -S . -B build -DPRIDE_MPI=ON && cmake "
            "--build build` (a build configured before Open MPI was installed keeps PRIDE_MPI off until told)");
#endif
    // Claims in batches of 4 runs per thread: one transaction for several short runs, and still
    // small enough for two processes on one store to share the work evenly.
    Ledger ledger(c, store_path, 4 * static_cast<std::size_t>(jobs));
    return run_local(ledger, jobs, progress, stop, nullptr);
}

}  // namespace pride::engine
