#pragma once
// Two kinds of failure, because front ends answer them differently: bad input from the user (the
// command line: exit status 2, one line naming what and where) and everything else (exit status 1).
#include <stdexcept>
#include <string>

namespace pride {

/// Input that cannot be used: a bad parameter, an unknown name, a malformed file or number.
/// `where` names what was wrong in the library's own words (a spec field such as "start" or "dim",
/// a parameter, a file and line); front ends may translate it into their own (a flag, a key).
class InputError : public std::runtime_error {
  public:
    explicit InputError(const std::string& what) : std::runtime_error(what), detail_(what) {}
    InputError(const std::string& where, const std::string& detail)
        : std::runtime_error(where + ": " + detail), where_(where), detail_(detail) {}

    /// Empty when the error was built from a whole message.
    const std::string& where() const noexcept { return where_; }
    const std::string& detail() const noexcept { return detail_; }

  private:
    std::string where_;
    std::string detail_;
};

/// Throws InputError(where, what) unless `ok`; used to validate every parameter.
inline void require(bool ok, const std::string& where, const std::string& what) {
    if (!ok) throw InputError(where, what);
}

}  // namespace pride
