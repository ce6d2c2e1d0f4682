#pragma once
// [[suite]] name = "bbob-mixint" in a campaign file (toml.cpp's add_suite hands the table here).
// Internal to the campaign files' reader (it takes toml++'s nodes; not installed).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "experiment/campaign/campaign.hpp"

namespace pride::campaign {

/// Called once with what the suite expands to, before any problem is made: the number of
/// problems, the memory they need, where to blame and the words to begin a refusal with.
using ExpandCheck =
    std::function<void(std::size_t problems, double memory, const std::string& where, const std::string& what)>;

/// COCO's mixed-integer suite: `functions` (1-24, default all), `instances` (from 1, default 1-5
/// as bbob's), `dimensions` (required; multiples of 5 from 5 to 40, the suite's own below its
/// largescale ones being 5, 10, 20, 40); one problem per (function, dimension, instance),
/// "PREFIX-fN-iK-dD" on bbob-mixint-fN. A bad list is an InputError at its key.
void add_bbob_mixint_suite(std::vector<CampaignProblem>& out, const std::string& file, const toml::table& t,
                           const ExpandCheck& expand);

}  // namespace pride::campaign
