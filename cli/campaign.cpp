#include "cli/campaign.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <thread>

#include "engine/campaign.hpp"
#include "engine/campaign_toml.hpp"

namespace pride::cli {

int bench_command(const BenchOptions& o, std::ostream& out) {
    const engine::Campaign c = engine::read_campaign(o.config);
    const std::string store =
        o.out.empty() ? std::filesystem::path(o.config).replace_extension(".sqlite").string() : o.out;
    const std::int64_t jobs = o.jobs.value_or(std::max(1u, std::thread::hardware_concurrency()));
    const bool show_progress = isatty(STDERR_FILENO) != 0;
    engine::Progress progress;
    if (show_progress)
        progress = [](std::size_t done, std::size_t total, double seconds) {
            fmt::print(stderr, "\r{}/{} runs, {:.0f} s elapsed   ", done, total, seconds);
        };
    const engine::BenchSummary s = engine::run_campaign(c, store, jobs, progress);
    if (show_progress) fmt::print(stderr, "\n");
    if (s.ranks > 1)
        out << fmt::format("{}: {} runs stored in {} ({} were there already, {} in all; {} MPI ranks)\n", c.name,
                           s.stored, store, s.already, s.total, s.ranks);
    else
        out << fmt::format("{}: {} runs stored in {} ({} were there already, {} in all)\n", c.name, s.stored, store,
                           s.already, s.total);
    return 0;
}

}  // namespace pride::cli
