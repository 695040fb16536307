#pragma once
// pt-render's usage text: the whole of it (pt-render --help) and each command's part with the
// option groups it takes (pt-render COMMAND --help).
#include <optional>
#include <string>
#include <vector>

namespace pt::cli {

std::string fullUsage();
// The usage of one command; nullopt for a name that is no command.
std::optional<std::string> commandUsage(const std::string& command);
// Whether the arguments after the command ask for its usage (--help or -h anywhere).
bool asksForHelp(const std::vector<std::string>& args);

}  // namespace pt::cli
