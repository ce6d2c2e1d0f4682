#pragma once
// The subcommands, separated from argument parsing so that each reads like its contract in
// docs/cli.md. Each writes its whole output only once it has succeeded.
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "engine/params.hpp"
#include "engine/specs.hpp"

namespace pride::cli {

struct RunOptions {
    std::string problem;
    std::int64_t dim = 0;
    std::optional<std::int64_t> instance;
    std::string algo;
    engine::Budget budget;            // --evals, --iters, --target, --wall-ms, --threads
    std::optional<std::string> pop;   // as given: its range is the algorithm's
    std::uint64_t seed = 1;           // every 64-bit value is a seed (flags.hpp: max_seed)
    std::vector<std::string> params;  // "name=value"
    bool json = false;
};
int run_command(const RunOptions& o, std::ostream& out);

/// "name=value" assignments (--param), with the population of --pop when given.
engine::ParamValues parse_params(const std::vector<std::string>& assignments, const std::optional<std::string>& pop);

struct EvalOptions {
    std::string problem;
    std::string x;  // "v1,v2,..." or "-" for stdin
    std::optional<std::int64_t> dim;
    std::optional<std::int64_t> instance;
    std::uint64_t seed = 0;  // the noise of a noisy function (quartic-noise)
};
int eval_command(const EvalOptions& o, std::istream& in, std::ostream& out);

/// `pride list`: text, one JSON object, or the markdown tables docs/cli.md includes.
enum class ListFormat { text, json, markdown };
int list_command(ListFormat format, std::ostream& out);

}  // namespace pride::cli
