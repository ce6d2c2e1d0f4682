#pragma once
// Parameters declared once: each algorithm in the registry lists its parameters (name, type,
// default, allowed range, one line of doc), and every front end (command line, campaign files,
// Python) checks what a user gives against that list before anything is built or allocated.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pride::engine {

/// choice: one of a list of names (`shortcut = line`); the value held is the name's index.
enum class ParamType { integer, real, flag, choice };

std::string_view to_string(ParamType t);

struct ParamSpec {
    std::string name;
    ParamType type = ParamType::real;
    std::optional<double> default_value;  // empty: the algorithm's own rule (doc says which)
    double min = 0.0;                     // allowed range, both ends included unless open
    double max = 0.0;
    std::string doc;
    bool min_open = false;
    bool max_open = false;
    bool box_only = false;             // has no meaning on chains (SBX's index, say): refused there when set
    bool chain_only = false;           // a setting of the chain space (a shortcut, say): refused on boxes when set
    bool grid_only = false;            // how a grid is planned on (its encoding, say): refused on other problems
    bool constrained_only = false;     // how constraints are handled: refused on problems without any
    std::vector<std::string> choices;  // choice: the names, in index order

    ParamSpec& open_below() {
        min_open = true;
        return *this;
    }
    ParamSpec& open_above() {
        max_open = true;
        return *this;
    }
    ParamSpec& only_on_boxes() {
        box_only = true;
        return *this;
    }
    ParamSpec& only_on_chains() {
        chain_only = true;
        return *this;
    }
    ParamSpec& only_on_grids() {
        grid_only = true;
        return *this;
    }
    ParamSpec& only_with_constraints() {
        constrained_only = true;
        return *this;
    }
    /// No default: the algorithm's own rule applies unless the user sets a value (doc says which).
    ParamSpec& no_default() {
        default_value.reset();
        return *this;
    }

    /// "[2, 10000000]", "(0, 1]", "0 or 1", "none, line or elbow".
    std::string range() const;
    /// The default as text: "0.9", "1", "line"; "none" when there is no default.
    std::string default_text() const;
    /// The index of `name` among the choices, or an InputError naming them.
    double choice_index(const std::string& name, const std::string& where) const;
    /// Throws InputError("<where>: ...") unless `v` has the type and lies in the range.
    void check(double v, const std::string& where) const;
};

ParamSpec integer(std::string name, std::int64_t default_value, std::int64_t min, std::int64_t max, std::string doc);
ParamSpec real(std::string name, double default_value, double min, double max, std::string doc);
ParamSpec flag(std::string name, bool default_value, std::string doc);
/// A parameter that takes one of `choices` by name; `default_value` must be one of them.
ParamSpec choice(std::string name, std::vector<std::string> choices, const std::string& default_value, std::string doc);

/// What a user set, by name: "pop=20" on the command line, `pop = 20` in a campaign file, pop=20 in
/// Python. Values are numbers (flags 0 or 1) or names (for choice parameters, `shortcut=line`),
/// checked against the algorithm's declarations by Params; a later set of the same name wins.
class ParamValues {
  public:
    void set(const std::string& name, double value) {
        names_.erase(name);
        values_[name] = value;
    }
    void set_name(const std::string& name, const std::string& value) {
        values_.erase(name);
        names_[name] = value;
    }
    /// Parses "name=value": a finite number, else a name; InputError naming the assignment when it
    /// is not NAME=VALUE.
    void set_from_string(std::string_view assignment);
    bool contains(const std::string& name) const { return values_.count(name) != 0 || names_.count(name) != 0; }
    std::optional<double> find(const std::string& name) const;
    bool empty() const { return values_.empty() && names_.empty(); }
    const std::map<std::string, double>& values() const { return values_; }
    const std::map<std::string, std::string>& names() const { return names_; }

  private:
    std::map<std::string, double> values_;
    std::map<std::string, std::string> names_;
};

/// The parameters of one algorithm after checking: every declared name with the user's value or
/// its default. Asking for an undeclared name is a bug in the algorithm's registration.
class Params {
  public:
    Params() = default;
    /// Checks `given` against `specs`: an unknown name, a wrong type or a value out of range is an
    /// InputError naming `algorithm`, the parameter and its range.
    Params(const std::string& algorithm, const std::vector<ParamSpec>& specs, const ParamValues& given);

    double real(const std::string& name) const;
    std::int64_t integer(const std::string& name) const;
    bool flag(const std::string& name) const;
    /// A choice parameter's name (its value, or its default).
    const std::string& choice(const std::string& name) const;
    /// Empty when the parameter has no default and the user did not set it.
    std::optional<double> optional(const std::string& name) const;
    bool given(const std::string& name) const { return given_.count(name) != 0; }

  private:
    const std::optional<double>& at(const std::string& name) const;
    std::string algorithm_;
    std::map<std::string, std::vector<std::string>> choices_;  // the names of the choice parameters
    std::map<std::string, std::optional<double>> values_;
    std::map<std::string, double> given_;
};

}  // namespace pride::engine
