#pragma once
// `pride bench CONFIG.toml [--jobs N] [--out STORE] [--shard K/N]`: a campaign file run into an
// SQLite store by the engine (experiment/campaign.hpp); this is only the command's parsing and printing.
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>

#include "experiment/campaign/run.hpp"

namespace pride::cli {

struct BenchOptions {
    std::string config;
    std::optional<std::int64_t> jobs;  // default: the number of cores
    std::string out;                   // default: the campaign file's name with .sqlite, in the working folder
    std::optional<std::string> shard;  // "K/N": part K of N of the runs (default: all)
};
int bench_command(const BenchOptions& o, std::ostream& out);

/// `--shard K/N`: two integers written in full, 1 <= K <= N; an InputError naming --shard otherwise.
campaign::Shard parse_shard(std::string_view text);

}  // namespace pride::cli
