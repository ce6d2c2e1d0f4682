#pragma once
// Runs the `pride` executable as a user would and captures what it prints, for the command-line
// tests: exit status, stdout and stderr, with optional text on stdin.
#include <sys/wait.h>

#include <unistd.h>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/test_support.hpp"

namespace pride::test {

struct CliOutput {
    int status = -1;
    std::string out;
    std::string err;
};

/// `args` is appended to the path of pride and run by /bin/sh, so quote as in a shell; `cwd`, when
/// not empty, is the folder it runs in.
inline CliOutput run_pride_in(const std::string& cwd, const std::string& args, const std::string& stdin_text = "") {
    char dir_template[] = "/tmp/pride-test-XXXXXX";
    const char* dir = mkdtemp(dir_template);
    if (!dir) throw std::runtime_error("mkdtemp failed");
    const std::string base(dir);
    { std::ofstream(base + "/in") << stdin_text; }
    const std::string cmd = (cwd.empty() ? std::string() : "cd '" + cwd + "' && ") + std::string("'") + PRIDE_EXE +
                            "' " + args + " <" + base + "/in >" + base + "/out 2>" + base + "/err";
    const int raw = std::system(cmd.c_str());
    auto slurp = [](const std::string& path) {
        std::ifstream f(path);
        std::stringstream s;
        s << f.rdbuf();
        return s.str();
    };
    CliOutput r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(base + "/out");
    r.err = slurp(base + "/err");
    std::remove((base + "/in").c_str());
    std::remove((base + "/out").c_str());
    std::remove((base + "/err").c_str());
    rmdir(base.c_str());
    return r;
}

inline CliOutput run_pride(const std::string& args, const std::string& stdin_text = "") {
    return run_pride_in("", args, stdin_text);
}

/// Runs `pride ARGS` and checks that it fails as bad input (check_input_error), naming `words`.
inline void expect_input_error(const std::string& args, const std::vector<std::string>& words = {},
                               const std::string& stdin_text = "") {
    INFO("pride " << args);
    check_input_error(run_pride(args, stdin_text), words);
}

}  // namespace pride::test
