#pragma once
// The library names what is wrong in its own words (a spec field: "dim", "start", "encoding
// line", "parameter pop"); the command line says it in its flags (--dim, --start, --encoding line,
// --param pop). One table, used where an error reaches the user.
#include <string>

#include "framework/error.hpp"

namespace pride::cli {

/// The message of `e` with its `where` translated to the flag that set it, when there is one.
std::string user_message(const InputError& e);

}  // namespace pride::cli
