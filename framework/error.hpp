#pragma once
// Two kinds of failure, because the command line answers them differently: bad input from the user
// (exit status 2, one line naming what and where) and everything else (exit status 1).
#include <stdexcept>
#include <string>

namespace pride {

/// Input that cannot be used: a bad parameter, an unknown name, a malformed file or number.
class InputError : public std::runtime_error {
  public:
    explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

/// Throws InputError("<where>: <what>") unless `ok`; used to validate every parameter.
inline void require(bool ok, const std::string& where, const std::string& what) {
    if (!ok) throw InputError(where + ": " + what);
}

}  // namespace pride
