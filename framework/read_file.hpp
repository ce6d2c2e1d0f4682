#pragma once
// Reading a whole input file with a cap on its size, for every reader of outside data (maps,
// scenarios, CSV tables, campaign files). The cap is checked before each chunk is kept, so an
// endless stream (/dev/zero, a pipe) is refused after at most `max_bytes` of memory, not when the
// machine runs out of it; a regular file is refused from its size before anything is read.
#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "framework/error.hpp"

namespace pride {

/// The content of the file at `path`, at most `max_bytes` of it. InputError "PATH: cannot open:
/// REASON", "PATH: is a folder, not a file", "PATH: cannot read: REASON" or "PATH: too large:
/// more than N MiB (WHAT files are far smaller)" otherwise.
inline std::string read_capped_file(const std::string& path, std::size_t max_bytes, const std::string& what) {
    struct Closer {
        void operator()(std::FILE* f) const { std::fclose(f); }
    };
    const auto too_large = [&] {
        return InputError(path + ": too large: more than " + std::to_string(max_bytes >> 20) + " MiB (" + what +
                          " files are far smaller)");
    };
    errno = 0;
    std::unique_ptr<std::FILE, Closer> f(std::fopen(path.c_str(), "rb"));
    if (!f) throw InputError(path + ": cannot open: " + std::strerror(errno));
    struct stat st {};
    if (fstat(fileno(f.get()), &st) == 0) {
        if (S_ISDIR(st.st_mode)) throw InputError(path + ": is a folder, not a file");
        if (S_ISREG(st.st_mode) && static_cast<unsigned long long>(st.st_size) > max_bytes) throw too_large();
    }
    std::string data;
    if (S_ISREG(st.st_mode)) data.reserve(static_cast<std::size_t>(st.st_size));
    char buffer[1 << 16];
    for (;;) {
        const std::size_t n = std::fread(buffer, 1, sizeof buffer, f.get());
        if (n > max_bytes - data.size()) throw too_large();
        data.append(buffer, n);
        if (n < sizeof buffer) break;
    }
    if (std::ferror(f.get())) {
        const int err = errno;
        throw InputError(path + ": cannot read: " + (err ? std::strerror(err) : "read error"));
    }
    return data;
}

}  // namespace pride
