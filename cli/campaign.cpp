#include "cli/campaign.hpp"

#include "cli/stderr.hpp"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <thread>

#include "cli/flags.hpp"
#include "cli/numbers.hpp"
#include "experiment/campaign/run.hpp"
#include "experiment/campaign/toml.hpp"

namespace pride::cli {
namespace {

std::atomic<int> stop_signal{0};  // lock-free: written by the signal handler

extern "C" void on_signal(int signal) {
    stop_signal.store(signal);
}

/// SIGINT and SIGTERM stop the campaign between commits (run_campaign polls the flag); a second
/// one kills the process at once (SA_RESETHAND).
void catch_signals() {
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

campaign::Shard parse_shard(std::string_view text) {
    const std::string usage =
        "must be K/N, part K of N with integers 1 <= K <= N (e.g. 2/3), got '" + printable(text) + "'";
    const auto slash = text.find('/');
    require(slash != std::string_view::npos && text.find('/', slash + 1) == std::string_view::npos, "--shard", usage);
    const std::string_view k = text.substr(0, slash), n = text.substr(slash + 1);
    try {
        check_integer(n, 1, max_count, "");
        check_integer(k, 1, max_count, "");
    } catch (const InputError&) {
        throw InputError("--shard", usage);
    }
    campaign::Shard shard{std::stoll(std::string(k)), std::stoll(std::string(n))};
    require(shard.index <= shard.count, "--shard", usage);
    return shard;
}

int bench_command(const BenchOptions& o, std::ostream& out) {
    const campaign::Shard shard = o.shard ? parse_shard(*o.shard) : campaign::Shard{};
    const campaign::Campaign c = campaign::read_campaign(o.config);
    // By default in the working folder, not beside the campaign file (which may be in a
    // checkout or a read-only place); the summary line says where.
    const std::string store =
        o.out.empty() ? std::filesystem::path(o.config).filename().replace_extension(".sqlite").string() : o.out;
    // Under mpirun every rank is a process of its own: one thread each unless --jobs says more.
    const std::int64_t jobs =
        o.jobs.value_or(campaign::launched_ranks() > 1 ? 1 : std::max(1u, std::thread::hardware_concurrency()));
    const bool show_progress = isatty(STDERR_FILENO) != 0;
    campaign::Progress progress;
    if (show_progress)
        progress = [](std::size_t done, std::size_t total, double seconds) {
            print_stderr("\r{}/{} runs, {:.0f} s elapsed   ", done, total, seconds);
        };
    campaign::Stop stop;
    stop.signal = &stop_signal;
    // The store is closed when this is called: the process ends here, abandoning the runs in
    // progress (nothing of theirs is in the store), with 128 + the signal as a shell reports it.
    stop.on_stop = [&](const campaign::Interrupted& i) {
        if (show_progress) print_stderr("\n");
        std::fflush(stdout);
        print_stderr("pride: interrupted by {}: {} of {} runs are stored in {}; run the same command again to resume\n",
                     i.signal == SIGINT    ? "SIGINT"
                     : i.signal == SIGTERM ? "SIGTERM"
                                           : "a signal",
                     i.in_store, i.total, store);
        std::fflush(stderr);
        std::_Exit(128 + i.signal);
    };
    catch_signals();
    const campaign::BenchSummary s = campaign::run_campaign(c, store, jobs, progress, stop, shard);
    if (show_progress) print_stderr("\n");
    if (s.ranks == 0) return 0;  // another MPI rank than 0: rank 0 prints the summary
    std::string extra = s.ranks > 1 ? fmt::format("; {} MPI ranks", s.ranks) : "";
    if (s.others > 0)
        extra += fmt::format("; {} being run by another pride bench on this store, or failed there", s.others);
    // "in all" counts this shard's runs; the campaign's are said beside them.
    if (o.shard)
        extra += fmt::format("; shard {}/{} of the campaign's {} runs", shard.index, shard.count,
                             c.problems.size() * c.algorithms.size() * static_cast<std::size_t>(c.seeds));
    out << fmt::format("{}: {} runs stored in {} ({} were there already, {} in all{})\n", c.name, s.stored, store,
                       s.already, s.total, extra);
    return 0;
}

}  // namespace pride::cli
