#pragma once
// The library names what is wrong in its own words (a spec field: "dim", "start", "encoding
// line", "parameter pop"); the command line says it in its flags (--dim, --start, --encoding line,
// --param pop). One table, used where an error reaches the user; and the checks of the numbers
// given to flags, so that a bad one gets pride's own line (the flag, the accepted range) rather
// than the argument parser's.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "engine/run.hpp"
#include "framework/error.hpp"

namespace pride::cli {

/// The message of `e` with its `where` translated to the flag that set it, when there is one.
std::string user_message(const InputError& e);

/// `text` safe to print on a terminal: control bytes, DEL and bytes that are not UTF-8 become
/// \xHH (\n, \r, \t as such), a backslash stays one. Every error line goes through it, since
/// errors quote what the user gave (file names, map rows, values, CSV cells).
std::string printable(std::string_view text);

/// A check for an integer flag: an integer written in full in [min, max]; anything else (a
/// fraction, "1e3", a value out of range, not a number) is refused naming the flag and the range.
CLI::Validator integer_in(std::int64_t min, std::uint64_t max);

/// A check for a real flag: a finite number ("nan", "inf", "1e999" are refused), in [min, max]
/// when those are finite.
CLI::Validator finite_in(double min = -std::numeric_limits<double>::infinity(),
                         double max = std::numeric_limits<double>::infinity());

/// A check for a flag or argument that names a file or folder: the empty name is refused (no file
/// has it; a flag given '' was ignored as if not given).
CLI::Validator a_path();

/// The largest count (evaluations, iterations, population, dimension) a flag accepts: the
/// engine's (engine::max_budget).
inline constexpr std::uint64_t max_count = engine::max_budget;
/// Seeds: the random generators take 64 bits, so every seed in [0, 2^64 - 1] is its own stream.
inline constexpr std::uint64_t max_seed = std::numeric_limits<std::uint64_t>::max();
/// Instances are numbered by signed 64-bit integers.
inline constexpr std::uint64_t max_instance = std::numeric_limits<std::int64_t>::max();

}  // namespace pride::cli
