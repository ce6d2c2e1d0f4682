#include "experiment/campaign/toml_nodes.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "experiment/campaign/campaign.hpp"
#include "framework/error.hpp"

namespace pride::campaign::toml_nodes {

std::string at(const std::string& file, const toml::node& node) {
    return fmt::format("{}:{}", file, node.source().begin.line);
}

std::string at_column(const std::string& file, const toml::node& node) {
    return fmt::format("{}:{}:{}", file, node.source().begin.line, node.source().begin.column);
}

[[noreturn]] void fail(const std::string& where, const std::string& what) {
    throw InputError(where + ": " + what);
}

std::string need_string(const std::string& file, const toml::table& t, std::string_view key, const std::string& where) {
    const toml::node* n = t.get(key);
    if (!n) fail(where, "missing key '" + std::string(key) + "'");
    if (!n->is_string()) fail(at(file, *n), "'" + std::string(key) + "' must be a string");
    return std::string(**n->as_string());
}

std::string need_name(const std::string& file, const toml::table& t, std::string_view key, const std::string& where) {
    std::string v = need_string(file, t, key, where);
    if (const std::string why = name_problem(v); !why.empty())
        fail(at_column(file, *t.get(key)), "'" + std::string(key) + "' " + why);
    return v;
}

std::int64_t need_integer(const std::string& file, const toml::node& n, std::string_view key) {
    if (!n.is_integer()) fail(at(file, n), "'" + std::string(key) + "' must be an integer");
    return **n.as_integer();
}

double need_number(const std::string& file, const toml::node& n, std::string_view key) {
    if (n.is_integer()) return static_cast<double>(**n.as_integer());
    if (!n.is_floating_point()) fail(at(file, n), "'" + std::string(key) + "' must be a number");
    return **n.as_floating_point();
}

std::vector<std::int64_t> need_integers(const std::string& file, const toml::node& n, std::string_view key) {
    const toml::array* a = n.as_array();
    if (!a) fail(at(file, n), "'" + std::string(key) + "' must be a list of integers");
    std::vector<std::int64_t> out;
    for (const toml::node& v : *a) out.push_back(need_integer(file, v, key));
    return out;
}

grid::Cell need_cell(const std::string& file, const toml::node& n, std::string_view key) {
    const toml::array* a = n.as_array();
    if (!a || a->size() != 2 || !(*a)[0].is_integer() || !(*a)[1].is_integer())
        fail(at(file, n), "'" + std::string(key) + "' must be [x, y] with two integers");
    const std::int64_t x = **(*a)[0].as_integer(), y = **(*a)[1].as_integer();
    if (std::abs(x) >= 1'000'000'000 || std::abs(y) >= 1'000'000'000)
        fail(at(file, n), "'" + std::string(key) + "' is far outside any map");
    return {static_cast<int>(x), static_cast<int>(y)};
}

grid::WorldPoint need_point(const std::string& file, const toml::node& n, std::string_view key) {
    const toml::array* a = n.as_array();
    const auto number = [](const toml::node& v) { return v.is_integer() || v.is_floating_point(); };
    if (!a || a->size() != 2 || !number((*a)[0]) || !number((*a)[1]))
        fail(at(file, n), "'" + std::string(key) + "' must be [x, y] with two numbers (metres in the map's frame)");
    const grid::WorldPoint p{need_number(file, (*a)[0], key), need_number(file, (*a)[1], key)};
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail(at(file, n), "'" + std::string(key) + "' must be finite");
    return p;
}

}  // namespace pride::campaign::toml_nodes
