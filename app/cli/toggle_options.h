#pragma once
// The renderer toggles as command-line flags, shared by render and bench (so every command
// spells them alike), and their report in stats JSON.
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli/cli_options.h"
#include "render/backend/backend.h"

namespace pt::cli {

// Every flag of the toggle table (render/backend/toggle_table.h): --no-nee, --megakernel, ...
const std::set<std::string>& toggleSwitches();
// --clamp X, --rebuild-ratio R
const std::set<std::string>& toggleValuedFlags();
IntegratorToggles parseToggles(const Options& options);

// {"nee": {"on": true}, "first_hit_cache": {"on": true, "active": false, "note": "..."}, ...}
nlohmann::ordered_json toggleStatesJson(const std::vector<ToggleState>& states);

// `a` plus every element of `b`.
std::set<std::string> joined(std::set<std::string> a, const std::set<std::string>& b);

}  // namespace pt::cli
