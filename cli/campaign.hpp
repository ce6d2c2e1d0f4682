#pragma once
// `pride bench CONFIG.toml [--jobs N] [--out STORE]`: a campaign file run into an SQLite store by
// the engine (experiment/campaign.hpp); this is only the command's parsing and printing.
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>

namespace pride::cli {

struct BenchOptions {
    std::string config;
    std::optional<std::int64_t> jobs;  // default: the number of cores
    std::string out;                   // default: the campaign file's name with .sqlite, in the working folder
};
int bench_command(const BenchOptions& o, std::ostream& out);

}  // namespace pride::cli
