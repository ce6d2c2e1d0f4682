#pragma once
// Reading the values of a campaign file's nodes (toml++): where a node is, for messages, and a
// value of the type a key needs, or one InputError naming the file, the line and the key. Internal
// to the campaign files' reader (toml.cpp, toml_seeds.cpp; it takes toml++'s nodes; not installed).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "problems/grid/map.hpp"

namespace pride::campaign::toml_nodes {

/// FILE:LINE of a node.
std::string at(const std::string& file, const toml::node& node);

/// FILE:LINE:COLUMN of a node, for the newer checks (the older ones give the line).
std::string at_column(const std::string& file, const toml::node& node);

/// Throws InputError("WHERE: WHAT").
[[noreturn]] void fail(const std::string& where, const std::string& what);

/// The string value of key `key` of `t` (`where`: the table's place, for a missing key).
std::string need_string(const std::string& file, const toml::table& t, std::string_view key, const std::string& where);

/// A name the store keeps and summaries print (an id, the campaign's name): need_string, and not
/// empty, without NUL or another control character (campaign.hpp: name_problem).
std::string need_name(const std::string& file, const toml::table& t, std::string_view key, const std::string& where);

std::int64_t need_integer(const std::string& file, const toml::node& n, std::string_view key);

double need_number(const std::string& file, const toml::node& n, std::string_view key);

/// An array of integers.
std::vector<std::int64_t> need_integers(const std::string& file, const toml::node& n, std::string_view key);

/// [x, y] with two integers.
grid::Cell need_cell(const std::string& file, const toml::node& n, std::string_view key);

/// [x, y] with two finite numbers: a world point in metres (start_world, goal_world).
grid::WorldPoint need_point(const std::string& file, const toml::node& n, std::string_view key);

}  // namespace pride::campaign::toml_nodes
