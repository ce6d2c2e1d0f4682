#pragma once
// Small helpers shared by the tests: a temporary folder, whole-file reads, the public data of
// others found through PRIDE_DATA, lines of a text, the numbers of a JSON array, and the check of
// the command line's bad-input contract.
#include <stdlib.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "tests/json_reader.hpp"

// AddressSanitizer reserves terabytes of address space for its shadow memory, so a process under
// an address-space limit (`ulimit -v`, what available_memory() honours) cannot even start there:
// the tests of such limits run in the normal build only. (GCC says ASan with
// __SANITIZE_ADDRESS__, clang with __has_feature.)
#if defined(__SANITIZE_ADDRESS__)
#define PRIDE_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PRIDE_UNDER_ASAN 1
#endif
#endif
#ifndef PRIDE_UNDER_ASAN
#define PRIDE_UNDER_ASAN 0
#endif

namespace pride::test {

/// A temporary folder under /tmp, removed with everything in it at the end of the scope.
class TempDir {
  public:
    explicit TempDir(const std::string& prefix = "pride-test") {
        std::string pattern = "/tmp/" + prefix + "-XXXXXX";
        if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return path_; }
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    std::string write(const std::string& name, const std::string& content) const {
        std::ofstream(path_ / name, std::ios::binary) << content;
        return file(name);
    }
    /// The names in the folder, sorted.
    std::vector<std::string> entries() const {
        std::vector<std::string> out;
        for (const auto& e : std::filesystem::directory_iterator(path_)) out.push_back(e.path().filename().string());
        std::sort(out.begin(), out.end());
        return out;
    }

  private:
    std::filesystem::path path_;
};

/// The whole file, bytes as they are.
inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

/// `$PRIDE_DATA/relative`: a file or folder of the public data written by others that the
/// repository does not hold (Moving AI maps, nav2's ROS maps, jMetal's fronts; laid out as
/// README.md says). Without PRIDE_DATA, or without that file under it, prints the one line
/// "skipped: needs $PRIDE_DATA/relative (what), why" and gives nothing: the test then returns,
/// and passes, without checking what needs the data.
inline std::optional<std::filesystem::path> shared_data(const std::string& relative, const std::string& what) {
    const char* root = std::getenv("PRIDE_DATA");
    std::string why;
    if (!root || !*root)
        why = "not set";
    else if (const std::filesystem::path path = std::filesystem::path(root) / relative; std::filesystem::exists(path))
        return path;
    else
        why = "not found under " + std::string(root);
    std::cout << "skipped: needs $PRIDE_DATA/" << relative << " (" << what << "), " << why << std::endl;
    return std::nullopt;
}

/// The lines of `text`, without their '\n'; a last line without one counts.
inline std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const auto nl = text.find('\n', start);
        if (nl == std::string::npos) {
            lines.push_back(text.substr(start));
            break;
        }
        lines.push_back(text.substr(start, nl - start));
        start = nl + 1;
    }
    return lines;
}

/// The numbers of a JSON array of numbers.
inline std::vector<double> json_numbers(const JsonValue& array) {
    REQUIRE(array.kind == JsonValue::Kind::array);
    std::vector<double> out;
    for (const auto& item : array.items) {
        REQUIRE(item.kind == JsonValue::Kind::number);
        out.push_back(item.number);
    }
    return out;
}

/// The message of the InputError `f` throws; a marker string when it throws nothing (any other
/// exception propagates and fails the test).
template <class Fn>
std::string input_error_message(Fn&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "<no InputError thrown>";
}

/// The bad-input contract of every subcommand (docs/cli.md): exit status 2, nothing on
/// stdout, exactly one non-empty line on stderr, "pride: " first and '\n' last, naming each of
/// `words`. `R` is any outcome with `status`, `out` and `err`.
template <class R>
void check_input_error(const R& r, const std::vector<std::string>& words) {
    INFO("stdout: " << r.out);
    INFO("stderr: " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    REQUIRE(r.err.size() >= 2);
    CHECK(r.err.back() == '\n');
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err[r.err.size() - 2] != '\n');
    CHECK(r.err.find_first_not_of(" \t\n") != std::string::npos);
    CHECK(r.err.rfind("pride: ", 0) == 0);
    for (const auto& w : words) {
        INFO("the message should name '" << w << "'");
        CHECK(r.err.find(w) != std::string::npos);
    }
}

}  // namespace pride::test
