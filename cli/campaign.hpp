#pragma once
// Campaigns (issue 4): a TOML file names problems, algorithms, seeds and a budget; `pride bench`
// runs every (problem, algorithm, seed) on a thread pool and commits each finished run at once to
// an SQLite store, so that an interrupted campaign resumes with no run lost or run twice.
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace pride::cli {

struct ProblemSpec {
    std::string id;
    std::string type;  // a continuous problem name, or "grid"
    int line = 0;      // where it stands in the campaign file
    std::int64_t dim = 0;
    // grid only
    std::string map, start, goal, objective = "cells", encoding = "line", connector = "repair";
    std::string init;  // uniform, walk or rules; empty: each algorithm's own choice
    std::int64_t waypoints = 3, inflate = 0;
    std::optional<std::string> weights;
    std::optional<double> lambda;
};

struct AlgorithmSpec {
    std::string id;
    std::string type;                 // any algorithm name, nlopt:NAME included
    std::vector<std::string> params;  // "name=value"
    int line = 0;
};

struct Campaign {
    std::string file;  // for messages
    std::string text;  // the file itself, stored with the results
    std::string name;
    std::int64_t seeds = 0;
    std::optional<std::int64_t> evaluations, iterations;
    std::optional<double> target;  // a threshold for reports (evaluations to reach it); runs do not stop there
    std::vector<ProblemSpec> problems;
    std::vector<AlgorithmSpec> algorithms;
};

/// Reads and checks a campaign file: unknown keys, wrong types, duplicate ids, unknown problems or
/// algorithms and bad parameters are InputErrors naming the file, line and key. Every problem and
/// algorithm is built once here, so a campaign that starts will not fail half-way on its input.
Campaign read_campaign(const std::string& path);

/// One finished run, as stored.
struct RunRecord {
    std::string problem, algorithm;
    std::int64_t seed = 0;
    bool feasible = true;
    double best = 0.0;
    std::int64_t evaluations = 0, iterations = 0;
    double wall_ms = 0.0;
    std::optional<double> optimum;  // grid problems: the exact optimum (additive objectives)
    std::string solution;           // JSON: the best point, or the path as [[x,y],...]
    std::string history;            // JSON: best value after each iteration
    std::string history_evaluations;
};

/// Runs one (problem, algorithm, seed) of the campaign; the same inputs give the same record
/// (bar wall_ms), whatever thread runs it.
RunRecord run_one(const Campaign& c, const ProblemSpec& p, const AlgorithmSpec& a, std::int64_t seed);

struct BenchOptions {
    std::string config;
    std::optional<std::int64_t> jobs;  // default: the number of cores
    std::string out;                   // default: CONFIG with the extension .sqlite
};
int bench_command(const BenchOptions& o, std::ostream& out);

}  // namespace pride::cli
