// The command line's numbers, points and parameters: cli/numbers.hpp (parse_finite, parse_point),
// engine/params.hpp (NAME=VALUE assignments, checked against every registered algorithm's
// parameter list), cli/flags.hpp (the message translated to flags), and the stdin reader of
// `pride eval --x -` (cli/commands.hpp: eval_command), all on the same input. What they accept
// must be finite.
#include <cmath>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/flags.hpp"
#include "cli/numbers.hpp"
#include "engine/params.hpp"
#include "engine/registry.hpp"
#include "fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace pride;
    const std::string_view in = fuzz::text(data, size);
    const auto message = [](const InputError& e) { fuzz::expect(!cli::user_message(e).empty(), "an empty message"); };
    try {
        fuzz::expect(std::isfinite(cli::parse_finite(in, "dim")), "parse_finite accepted a non-finite value");
    } catch (const InputError& e) {
        message(e);
    }
    try {
        for (const double v : cli::parse_point(in, "start")) fuzz::expect(std::isfinite(v), "a non-finite coordinate");
    } catch (const InputError& e) {
        message(e);
    }
    // Each line an assignment; then the set checked against every algorithm's parameters.
    engine::ParamValues values;
    try {
        std::size_t start = 0;
        while (start <= in.size()) {
            const std::size_t nl = in.find('\n', start);
            const std::string_view line = in.substr(start, nl == in.npos ? in.npos : nl - start);
            values.set_from_string(line);
            if (nl == in.npos) break;
            start = nl + 1;
        }
    } catch (const InputError& e) {
        message(e);
    }
    for (const auto& [name, v] : values.values()) fuzz::expect(std::isfinite(v), "a non-finite parameter value");
    for (const auto& a : engine::algorithms().entries()) {
        try {
            const engine::Params p(a.name, a.params, values);
        } catch (const InputError& e) {
            message(e);
        }
    }
    // pride eval --problem sphere --x - with the input on stdin.
    try {
        cli::EvalOptions o;
        o.problem = "sphere";
        o.x = "-";
        std::istringstream stdin_text{std::string(in)};
        std::ostringstream out;
        cli::eval_command(o, stdin_text, out);
    } catch (const InputError& e) {
        message(e);
    }
    return 0;
}
