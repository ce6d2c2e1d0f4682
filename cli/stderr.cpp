#include "cli/stderr.hpp"

#include <unistd.h>

#include <cerrno>

namespace pride::cli {

void write_stderr(std::string_view text) noexcept {
    while (!text.empty()) {
        const ssize_t n = ::write(STDERR_FILENO, text.data(), text.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;  // lost: nothing left to tell it to
        text.remove_prefix(static_cast<std::size_t>(n));
    }
}

}  // namespace pride::cli
