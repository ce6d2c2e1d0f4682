#pragma once
// Reading a whole input file with a cap on its size, for every reader of outside data (maps,
// scenarios, CSV tables, campaign files). The cap is checked before each chunk is kept, so an
// endless standard input (`yes | pride path --map /dev/stdin`) is refused after at most
// `max_bytes` of memory, not when the machine runs out of it; a regular file is refused from its
// size before anything is read.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <string>

#include "framework/error.hpp"

namespace pride {

/// The content of the file at `path`, at most `max_bytes` of it. Only regular files are read, and
/// standard input named /dev/stdin (a pipe there is the user's own): a FIFO, device or socket
/// elsewhere is refused at once, never waited on (a FIFO without a writer would block forever).
/// InputError "PATH: cannot open: REASON", "PATH: is a folder, not a file", "PATH: not a regular
/// file (KIND): ...", "PATH: cannot read: REASON" or "PATH: too large: more than N MiB (WHAT files
/// are far smaller)" otherwise.
///
/// `named_in_file`: the path was read from inside a file (a campaign's map, a scenario line's map,
/// a map_server YAML's image), not given on the user's own command line: then standard input is
/// refused by name too ("PATH: standard input is read only when named on the command line, not
/// inside a file"), as a file that names it would wait on whatever stdin is.
inline std::string read_capped_file(const std::string& path, std::size_t max_bytes, const std::string& what,
                                    bool named_in_file = false) {
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    };
    const auto too_large = [&] {
        return InputError(path + ": too large: more than " + std::to_string(max_bytes >> 20) + " MiB (" + what +
                          " files are far smaller)");
    };
    const bool names_stdin = path == "/dev/stdin" || path == "/dev/fd/0" || path == "/proc/self/fd/0";
    if (names_stdin && named_in_file)
        throw InputError(path + ": standard input is read only when named on the command line, not inside a file");
    const bool standard_input = names_stdin && !named_in_file;
    // O_NONBLOCK: opening a FIFO does not wait for a writer; fstat then refuses it.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | (standard_input ? 0 : O_NONBLOCK));
    if (fd < 0) {
        const int e = errno;
        throw InputError(path + ": cannot open: " + std::strerror(e));
    }
    const Closer closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        const int e = errno;
        throw InputError(path + ": cannot read: " + std::strerror(e));
    }
    if (S_ISDIR(st.st_mode)) throw InputError(path + ": is a folder, not a file");
    if (!S_ISREG(st.st_mode) && !standard_input) {
        const char* kind = S_ISFIFO(st.st_mode)   ? "a FIFO"
                           : S_ISCHR(st.st_mode)  ? "a character device"
                           : S_ISBLK(st.st_mode)  ? "a block device"
                           : S_ISSOCK(st.st_mode) ? "a socket"
                                                  : "not a file";
        throw InputError(path + ": not a regular file (" + kind + "): " + what +
                         (named_in_file ? " files named inside a file are read from regular files only"
                                        : " files are read from regular files, or from standard input as /dev/stdin"));
    }
    if (S_ISREG(st.st_mode) && static_cast<unsigned long long>(st.st_size) > max_bytes) throw too_large();
    if (!standard_input) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    std::string data;
    if (S_ISREG(st.st_mode)) data.reserve(static_cast<std::size_t>(st.st_size));
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const int e = errno;
            throw InputError(path + ": cannot read: " + std::strerror(e));
        }
        if (n == 0) break;
        if (static_cast<std::size_t>(n) > max_bytes - data.size()) throw too_large();
        data.append(buffer, static_cast<std::size_t>(n));
    }
    return data;
}

}  // namespace pride
