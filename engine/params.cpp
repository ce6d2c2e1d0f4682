#include "engine/params.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "framework/error.hpp"
#include "framework/number.hpp"

namespace pride::engine {

std::string_view to_string(ParamType t) {
    switch (t) {
        case ParamType::integer:
            return "integer";
        case ParamType::real:
            return "real";
        case ParamType::flag:
            return "flag";
        case ParamType::choice:
            return "choice";
    }
    return "real";
}

namespace {
std::string number(double v) {
    return fmt::format("{}", v);
}
/// A value for an integer's message: whole numbers written out in full (9223372036854775807 from
/// a campaign or Python is 9223372036854775808 as a double, never 9.223372036854776e+18).
std::string integer_text(double v) {
    return std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e21 ? fmt::format("{:.0f}", v) : number(v);
}
}  // namespace

std::string ParamSpec::range() const {
    if (type == ParamType::flag) return "0 or 1";
    if (type == ParamType::choice) {
        std::string out;
        for (std::size_t i = 0; i < choices.size(); ++i)
            out += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
        return out;
    }
    return fmt::format("{}{}, {}{}", min_open ? "(" : "[", number(min), number(max), max_open ? ")" : "]");
}

std::string ParamSpec::default_text() const {
    if (!default_value) return "none";
    if (type == ParamType::choice) return choices.at(static_cast<std::size_t>(*default_value));
    return number(*default_value);
}

double ParamSpec::choice_index(const std::string& value, const std::string& where) const {
    for (std::size_t i = 0; i < choices.size(); ++i)
        if (choices[i] == value) return static_cast<double>(i);
    throw InputError(where, fmt::format("{} must be {} ({}), got '{}'", name, range(), doc, value));
}

void ParamSpec::check(double v, const std::string& where) const {
    require(type != ParamType::choice, where,
            fmt::format("{} takes a name: {} ({}), got the number {}", name, range(), doc, number(v)));
    require(std::isfinite(v), where, fmt::format("{} must be a finite number in {}, got {}", name, range(), number(v)));
    const bool integral = v == std::floor(v) && std::abs(v) < 9.0e15;
    const bool above = min_open ? v > min : v >= min;
    const bool below = max_open ? v < max : v <= max;
    // An integer out of its range or not whole: one message with the range, whichever it is.
    if (type == ParamType::integer)
        require(integral && above && below, where,
                fmt::format("{} must be an integer in {} ({}), got {}", name, range(), doc, integer_text(v)));
    if (type == ParamType::flag) require(integral, where, fmt::format("{} must be 0 or 1, got {}", name, number(v)));
    require(std::isfinite(v) && above && below, where,
            fmt::format("{} must be in {} ({}), got {}", name, range(), doc, number(v)));
}

namespace {
ParamSpec spec(std::string name, ParamType type, std::optional<double> default_value, double min, double max,
               std::string doc) {
    ParamSpec s;
    s.name = std::move(name);
    s.type = type;
    s.default_value = default_value;
    s.min = min;
    s.max = max;
    s.doc = std::move(doc);
    return s;
}
}  // namespace

ParamSpec integer(std::string name, std::int64_t default_value, std::int64_t min, std::int64_t max, std::string doc) {
    return spec(std::move(name), ParamType::integer, static_cast<double>(default_value), static_cast<double>(min),
                static_cast<double>(max), std::move(doc));
}

ParamSpec real(std::string name, double default_value, double min, double max, std::string doc) {
    return spec(std::move(name), ParamType::real, default_value, min, max, std::move(doc));
}

ParamSpec flag(std::string name, bool default_value, std::string doc) {
    return spec(std::move(name), ParamType::flag, default_value ? 1.0 : 0.0, 0.0, 1.0, std::move(doc));
}

ParamSpec choice(std::string name, std::vector<std::string> choices, const std::string& default_value,
                 std::string doc) {
    ParamSpec s =
        spec(std::move(name), ParamType::choice, 0.0, 0.0, static_cast<double>(choices.size()) - 1.0, std::move(doc));
    s.choices = std::move(choices);
    s.default_value = s.choice_index(default_value, "choice");  // a registration bug otherwise
    return s;
}

void ParamValues::set_from_string(std::string_view assignment) {
    const auto eq = assignment.find('=');
    require(eq != std::string_view::npos && eq > 0, "parameter '" + std::string(assignment) + "'",
            "expected NAME=VALUE");
    const std::string name(assignment.substr(0, eq));
    const std::string text(assignment.substr(eq + 1));
    double value = 0.0;
    const NumberText read = parse_decimal(text, value);
    // A name (for a choice parameter, which Params checks) starts with a letter; anything else must
    // be a number (framework/number.hpp's grammar, as every other number). inf and nan are no
    // names: they are numbers that are not finite.
    auto not_finite = [](std::string t) {
        for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return t == "inf" || t == "nan" || t == "infinity";
    };
    auto name_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; };
    const bool is_name = !text.empty() && std::isalpha(static_cast<unsigned char>(text[0])) &&
                         std::all_of(text.begin(), text.end(), name_char) && !not_finite(text);
    if (is_name) {
        set_name(name, text);
        return;
    }
    require(read == NumberText::ok, "parameter " + name, number_problem(text, read));
    set(name, value);
}

std::optional<double> ParamValues::find(const std::string& name) const {
    if (names_.count(name) != 0) return std::nullopt;
    const auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

Params::Params(const std::string& algorithm, const std::vector<ParamSpec>& specs, const ParamValues& given)
    : algorithm_(algorithm) {
    auto declared = [&](const std::string& name) {
        for (const auto& s : specs)
            if (s.name == name) return &s;
        std::string known;
        for (const auto& s : specs) known += (known.empty() ? "" : ", ") + s.name;
        throw InputError(algorithm + ": unknown parameter '" + name + "' (" +
                         (known.empty() ? std::string("it takes none") : "parameters: " + known) + ")");
    };
    for (const auto& [name, value] : given.values()) {
        declared(name)->check(value, algorithm);
        given_[name] = value;
    }
    for (const auto& [name, text] : given.names()) {
        const ParamSpec* spec = declared(name);
        require(spec->type == ParamType::choice, algorithm,
                spec->type == ParamType::integer
                    ? fmt::format("{} must be an integer in {} ({}), got '{}'", name, spec->range(), spec->doc, text)
                    : fmt::format("{} must be a finite number in {}, got '{}'", name, spec->range(), text));
        given_[name] = spec->choice_index(text, algorithm);
    }
    for (const auto& s : specs)
        if (s.type == ParamType::choice) choices_[s.name] = s.choices;
    for (const auto& s : specs) {
        const auto it = given_.find(s.name);
        values_[s.name] = it != given_.end() ? std::optional<double>(it->second) : s.default_value;
    }
}

const std::optional<double>& Params::at(const std::string& name) const {
    const auto it = values_.find(name);
    if (it == values_.end()) throw std::logic_error(algorithm_ + ": asks for undeclared parameter '" + name + "'");
    return it->second;
}

double Params::real(const std::string& name) const {
    const auto& v = at(name);
    if (!v) throw std::logic_error(algorithm_ + ": parameter '" + name + "' has no value");
    return *v;
}

std::int64_t Params::integer(const std::string& name) const {
    return static_cast<std::int64_t>(real(name));
}

bool Params::flag(const std::string& name) const {
    return real(name) != 0.0;
}

const std::string& Params::choice(const std::string& name) const {
    const auto it = choices_.find(name);
    if (it == choices_.end()) throw std::logic_error(algorithm_ + ": parameter '" + name + "' is not a choice");
    return it->second.at(static_cast<std::size_t>(real(name)));
}

std::optional<double> Params::optional(const std::string& name) const {
    return at(name);
}

}  // namespace pride::engine
