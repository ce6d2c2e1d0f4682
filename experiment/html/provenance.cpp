#include "experiment/html/provenance.hpp"

#include <sys/utsname.h>

#include <ctime>

#include <fmt/format.h>

// The commit, written at every build by cmake/git_commit.cmake (experiment/html/CMakeLists.txt);
// the version, set on this file alone. A new commit recompiles nothing else.
#include "git_commit.hpp"
#ifndef PRIDE_VERSION
#define PRIDE_VERSION "unknown"
#endif

namespace pride::html {

Provenance provenance() {
    Provenance p;
    p.version = PRIDE_VERSION;
    p.commit = PRIDE_GIT_COMMIT;
#if defined(__clang__)
    p.compiler = "clang " __clang_version__;
#elif defined(__GNUC__)
    p.compiler = "gcc " __VERSION__;
#else
    p.compiler = "unknown";
#endif
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    p.date = fmt::format("{:04}-{:02}-{:02} {:02}:{:02}:{:02} UTC", utc.tm_year + 1900, utc.tm_mon + 1, utc.tm_mday,
                         utc.tm_hour, utc.tm_min, utc.tm_sec);
    struct utsname u {};
    if (uname(&u) == 0) {
        p.machine = fmt::format("{} {} {}", u.sysname, u.release, u.machine);
        p.host = u.nodename;
    } else {
        p.machine = p.host = "unknown";
    }
    return p;
}

}  // namespace pride::html
