#pragma once
// A campaign store (the SQLite file `pride bench` writes, docs/campaigns.md) read back and checked:
// every value the reports and exports use, typed. A store that cannot be used is bad input, never
// an internal error: InputError "STORE: not a campaign store (...)" for a file that is none, and
// DamagedStore "STORE: damaged store: WHERE: WHAT" for one whose tables, columns or values are not
// what pride bench writes.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "framework/error.hpp"

namespace pride::report {

/// A store whose contents are not what pride bench writes (missing tables or columns, values of
/// the wrong kind, malformed JSON); an InputError, so the command line exits 2.
class DamagedStore : public InputError {
  public:
    DamagedStore(const std::string& store, const std::string& what) : InputError(store + ": damaged store: " + what) {}
};

struct StoredRun {
    std::string problem, algorithm;
    std::int64_t seed = 0;
    std::optional<double> best;  // empty: no feasible value found
    std::int64_t evaluations = 0;
    double wall_ms = 0;
    std::optional<double> optimum;  // grid problems: the exact optimum
    // The best value after each iteration (+inf before the first feasible one) and, where
    // recorded, the evaluations spent by then (empty, or one per history value).
    std::vector<double> history;
    std::vector<std::int64_t> history_evaluations;
};

struct StoredProblem {
    std::string id;
    std::int64_t dim = 0;
};

struct CampaignStore {
    std::string name;
    std::optional<double> target;  // [budget] target; stores from before targets have none
    // In the campaign's order; empty optional for stores from before the problems table.
    std::optional<std::vector<StoredProblem>> problems;
    std::vector<StoredRun> runs;  // ordered by problem, algorithm, seed
};

/// Reads and checks the whole store at `path` (read-only). Throws InputError when the file is
/// missing or not a campaign store, DamagedStore when its contents are damaged.
CampaignStore read_store(const std::string& path);

}  // namespace pride::report
