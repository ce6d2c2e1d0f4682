#pragma once
// Campaign files (TOML): one front end of campaigns as data (campaign.hpp), for `pride bench`.
// Unknown keys, wrong types, duplicate ids, unknown problems or algorithms and bad parameters are
// InputErrors naming the file, line and key. docs/campaigns.md describes the format.
#include <string>

#include "experiment/campaign/campaign.hpp"

namespace pride::campaign {

/// Reads, checks and prepares (campaign.hpp: prepare) the campaign file at `path`.
Campaign read_campaign(const std::string& path);

/// read_campaign without prepare(): the file read and checked, its suites and instance lists
/// expanded, no problem built (so no map or data file read; the campaign's defaults not applied).
Campaign parse_campaign(const std::string& path);

}  // namespace pride::campaign
