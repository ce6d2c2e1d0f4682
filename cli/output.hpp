#pragma once
// The last step of a command that writes files and prints: its files are committed
// (framework/output_files.hpp) only once what it prints has reached standard output, so that
// `pride path --png p.png >/dev/full` fails leaving no p.png, as every failed command leaves
// nothing behind.
#include <cerrno>
#include <cstring>
#include <ostream>
#include <string_view>

#include "framework/error.hpp"
#include "framework/output_files.hpp"

namespace pride::cli {

/// Prints `text` to `out` and flushes it, then commits `files`. InputError "cannot write to
/// standard output: REASON" when the text cannot be written (`files` are then left to be discarded).
inline void print_then_commit(std::ostream& out, std::string_view text, OutputFiles& files) {
    errno = 0;
    out << text;
    out.flush();  // std::cout is synchronised with stdio: this is fflush(stdout), errno its reason
    if (!out) {
        const int e = errno;
        throw InputError(std::string("cannot write to standard output: ") +
                         (e != 0 ? std::strerror(e) : "write error"));
    }
    files.commit();
}

}  // namespace pride::cli
