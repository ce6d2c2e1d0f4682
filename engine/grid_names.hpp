#pragma once
// The names a grid spec takes (objectives, encodings, connectors, initial points), with a few words
// each: for listings, error messages, and the checks of a spec that need no map.
#include <string>
#include <vector>

#include "engine/specs.hpp"

namespace pride::engine {

struct NamedItem {
    std::string name;
    std::string summary;
};
const std::vector<NamedItem>& grid_objectives();
const std::vector<NamedItem>& grid_encodings();
const std::vector<NamedItem>& grid_connectors();
const std::vector<NamedItem>& grid_inits();

/// Whether `name` is one of `items`.
bool named_in(const std::vector<NamedItem>& items, const std::string& name);

/// The checks of a grid spec that need no map (names and their combinations): front ends call it
/// before reading a map, so a misspelt name is reported before a missing file.
void check_grid_names(const GridSpec& spec);

/// The objective a grid run of `algo` plans for when none is named: length for a planner of
/// polylines (the only objective it takes), cells for every other algorithm.
std::string default_grid_objective(const std::string& algo);

}  // namespace pride::engine
