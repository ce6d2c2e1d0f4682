#pragma once
// Writing to standard error from the command line's error paths. A message that cannot be
// written (stderr on a full disk, a closed pipe with SIGPIPE ignored) is lost, never an
// exception: fmt::print(stderr, ...) throws there, and from main's error handler that aborted
// the process (SIGABRT, 134) instead of exiting with the error's own status.
#include <fmt/format.h>

#include <string_view>
#include <utility>

namespace pride::cli {

/// Writes `text` to descriptor 2 (write(2), retried on EINTR and short writes); gives up
/// silently on any other failure. Never throws.
void write_stderr(std::string_view text) noexcept;

/// fmt::format, then write_stderr; a format failure (out of memory) loses the message too.
template <class... Args>
void print_stderr(fmt::format_string<Args...> format, Args&&... args) noexcept {
    try {
        write_stderr(fmt::format(format, std::forward<Args>(args)...));
    } catch (...) {
    }
}

}  // namespace pride::cli
