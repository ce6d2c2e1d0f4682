#pragma once
// Named numeric parameters as they arrive from the command line or a campaign file
// ("pop=20", "w_start=0.9"). Each read marks the name used, so that a misspelt name is an error
// rather than a silently ignored setting.
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <string_view>

#include "framework/error.hpp"

namespace pride {

class ParamMap {
  public:
    ParamMap() = default;

    /// Sets `name` to `value`; a later set of the same name wins.
    void set(const std::string& name, double value) { values_[name] = value; }

    /// Parses "name=value" (value a finite number).
    void set_from_string(std::string_view assignment) {
        const auto eq = assignment.find('=');
        require(eq != std::string_view::npos && eq > 0, "--param '" + std::string(assignment) + "'",
                "expected NAME=VALUE");
        const std::string name(assignment.substr(0, eq));
        const std::string text(assignment.substr(eq + 1));
        std::size_t used = 0;
        double value = 0.0;
        try {
            value = std::stod(text, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        require(used == text.size() && !text.empty() && std::isfinite(value), "--param " + name,
                "'" + text + "' is not a finite number");
        set(name, value);
    }

    bool contains(const std::string& name) const { return values_.count(name) != 0; }

    double get(const std::string& name, double fallback) const {
        used_.insert(name);
        const auto it = values_.find(name);
        return it == values_.end() ? fallback : it->second;
    }

    /// An integer parameter; a fractional value is an error naming `where`.
    std::int64_t get_int(const std::string& name, std::int64_t fallback, const std::string& where) const {
        const double v = get(name, static_cast<double>(fallback));
        require(v == std::floor(v) && std::abs(v) < 9.0e15, where,
                name + " must be an integer, got " + std::to_string(v));
        return static_cast<std::int64_t>(v);
    }

    /// Throws for the first name that was set but never read by `where`.
    void check_all_used(const std::string& where) const {
        for (const auto& [name, value] : values_)
            require(used_.count(name) != 0, where, "unknown parameter '" + name + "'");
    }

  private:
    std::map<std::string, double> values_;
    mutable std::set<std::string> used_;
};

}  // namespace pride
