#pragma once
// Where a report came from, as its page states it: which pride (version, and the git commit of its
// source when the build was configured), which compiler built it, when the report was made and on
// which machine.
#include <string>

namespace pride::html {

struct Provenance {
    std::string version;   // pride's (CMake's project version)
    std::string commit;    // `git describe --always --dirty` at configure time; "unknown" without git
    std::string compiler;  // the compiler's own words (__clang_version__, __VERSION__)
    std::string date;      // now, UTC: 2025-01-31 14:05:09 UTC
    std::string machine;   // uname: system, release, hardware ("Linux 6.1.0-13-amd64 x86_64")
    std::string host;      // the host name
};

Provenance provenance();

}  // namespace pride::html
