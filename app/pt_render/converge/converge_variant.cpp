#include "pt_render/converge/converge_variant.h"

#include <map>

#include "cli/cli_options.h"
#include "cli/guide_samples.h"
#include "cli/toggle_options.h"

namespace pt::cli {

namespace {

// The render command's flag for each value of a switch key ("" where the value is the default).
struct SwitchFlags {
    std::string on, off;
};

// The toggle table's keys with flags, and the denoiser (a display step, not a toggle).
const std::map<std::string, SwitchFlags>& switchKeys() {
    static const std::map<std::string, SwitchFlags> keys = [] {
        std::map<std::string, SwitchFlags> k = {{"denoise", {"--denoise", ""}}};
        for (const ToggleRow& row : toggleTable()) {
            if (*row.onFlag || *row.offFlag) k[row.key] = {row.onFlag, row.offFlag};
        }
        return k;
    }();
    return keys;
}

const std::map<std::string, std::string>& valuedKeys() {
    static const std::map<std::string, std::string> keys = {
        {"clamp", "--clamp"}, {"rebuild_ratio", "--rebuild-ratio"}, {"guide_samples", "--guide-samples"}};
    return keys;
}

std::string knownKeys() {
    std::string list;
    for (const auto& [key, flags] : switchKeys()) list += key + "=on|off, ";
    for (const auto& [key, flag] : valuedKeys()) list += key + "=X, ";
    return list.substr(0, list.size() - 2);
}

// One KEY=VALUE as render flags, appended to `flags`.
void appendFlags(const std::string& setting, std::vector<std::string>& flags) {
    const size_t equals = setting.find('=');
    if (equals == std::string::npos) throw UsageError("expected KEY=VALUE, got \"" + setting + "\"");
    const std::string key = setting.substr(0, equals), value = setting.substr(equals + 1);
    if (const auto valued = valuedKeys().find(key); valued != valuedKeys().end()) {
        flags.insert(flags.end(), {valued->second, value});
        return;
    }
    const auto switched = switchKeys().find(key);
    if (switched == switchKeys().end())
        throw UsageError("unknown key \"" + key + "\" (known: " + knownKeys() + ")");
    const bool on = value == "on" || value == "true" || value == "1";
    if (!on && value != "off" && value != "false" && value != "0") {
        throw UsageError(key + ": expected on or off, got \"" + value + "\"");
    }
    const std::string& flag = on ? switched->second.on : switched->second.off;
    if (!flag.empty()) flags.push_back(flag);
}

}  // namespace

ConvergeVariant parseVariant(const std::string& spec) {
    ConvergeVariant variant;
    variant.spec = spec;
    const size_t colon = spec.find(':');
    variant.name = spec.substr(0, colon);
    try {
        if (variant.name.empty()) throw UsageError("the variant needs a NAME before the colon");
        if (variant.name.find(',') != std::string::npos) throw UsageError("NAME may not contain a comma");
        std::vector<std::string> flags;
        if (colon != std::string::npos) {
            const std::string settings = spec.substr(colon + 1) + ",";
            for (size_t begin = 0, end; (end = settings.find(',', begin)) != std::string::npos;
                 begin = end + 1) {
                if (end > begin) appendFlags(settings.substr(begin, end - begin), flags);
            }
        }
        // --denoise and --guide-samples are the render command's, beside the toggles.
        const Options o(flags, joined(toggleValuedFlags(), {"--guide-samples"}),
                        joined(toggleSwitches(), {"--denoise"}));
        variant.denoise = o.has("--denoise");
        if (o.value("--guide-samples") && !variant.denoise)
            throw UsageError("guide_samples applies to denoise=on; give it");
        variant.guideSamples = guideSamplesOption(o);
        variant.toggles = parseToggles(o);
    } catch (const UsageError& e) {
        throw UsageError("--variant " + spec + ": " + e.what());
    }
    return variant;
}

}  // namespace pt::cli
