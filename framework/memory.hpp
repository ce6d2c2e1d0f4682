#pragma once
// The memory a process may use, and the check every front end makes before it allocates what a
// user's sizes ask for (a dimension, a population, a map, a history): one message naming the
// field, never std::bad_alloc after gigabytes.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "framework/error.hpp"

namespace pride {

/// Bytes of memory this machine has for one process: physical memory, or less when the kernel
/// says less is available without swapping (Linux's MemAvailable) or an address-space limit
/// (RLIMIT_AS, `ulimit -v`) is set.
inline double available_memory() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    double bytes = pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 1e18;
    if (std::FILE* f = std::fopen("/proc/meminfo", "r")) {
        char line[256];
        while (std::fgets(line, sizeof line, f))
            if (unsigned long long kb = 0; std::sscanf(line, "MemAvailable: %llu kB", &kb) == 1) {
                bytes = std::min(bytes, 1024.0 * static_cast<double>(kb));
                break;
            }
        std::fclose(f);
    }
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
        bytes = std::min(bytes, static_cast<double>(limit.rlim_cur));
    return bytes;
}

/// "12.5 GB", "300 MB": for messages.
inline std::string format_bytes(double bytes) {
    const char* unit = bytes >= 1e12 ? "TB" : bytes >= 1e9 ? "GB" : bytes >= 1e6 ? "MB" : "kB";
    const double scale = bytes >= 1e12 ? 1e12 : bytes >= 1e9 ? 1e9 : bytes >= 1e6 ? 1e6 : 1e3;
    char text[64];
    std::snprintf(text, sizeof text, "%.3g %s", bytes / scale, unit);
    return text;
}

/// InputError(where, "WHAT needs about N of memory, more than the M this machine has") when
/// `bytes` exceed available_memory().
inline void require_memory(double bytes, const std::string& where, const std::string& what) {
    const double have = available_memory();
    require(bytes <= have, where,
            what + " needs about " + format_bytes(bytes) + " of memory, more than the " + format_bytes(have) +
                " this machine has");
}

}  // namespace pride
