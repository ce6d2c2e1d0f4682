#pragma once
// A campaign's `protocol`: the runs a published comparison made, so that pride's runs and an
// imported published algorithm's share every cell of a report (docs/campaigns.md, "Published
// protocols"). A protocol fills in what the file leaves out and refuses what differs:
// - "bbob-2009", COCO's BBOB 2009 (Hansen, Auger, Finck, Ros 2009, "Real-parameter black-box
//   optimization benchmarking 2009: experimental setup"): bbob functions in dimensions 2, 3, 5, 10,
//   20 and 40, instances 1-5 with 3 trials each (seeds 1-3), the final target f_opt + 1e-8. The
//   budget was each entrant's own, so the file gives it ([budget] evaluations_per_dim, as COCO
//   states budgets).
// - "cec2017", "cec2022", "cec2020rw": the problems of that one suite, its runs per problem and
//   its MaxFES (what the campaign does by default for one CEC suite, here required).
#include <string>

#include "experiment/campaign/campaign.hpp"

namespace pride::campaign {

/// The names `protocol` takes, for messages.
inline constexpr const char* protocol_names = "bbob-2009, cec2017, cec2022, cec2020rw";

/// Whether `name` is a protocol.
bool is_protocol(const std::string& name);

/// Applies campaign.protocol (nothing when it is empty): InputError naming the file, the key and
/// what differs.
void apply_protocol(Campaign& campaign);

}  // namespace pride::campaign
