#include "cli/toggle_options.h"

namespace pt::cli {

const std::set<std::string>& toggleSwitches() {
    static const std::set<std::string> switches = [] {
        std::set<std::string> flags;
        for (const ToggleRow& row : toggleTable()) {
            for (const char* flag : {row.onFlag, row.offFlag}) {
                if (*flag) flags.insert(flag);
            }
        }
        return flags;
    }();
    return switches;
}

const std::set<std::string>& toggleValuedFlags() {
    static const std::set<std::string> flags = {"--clamp", "--rebuild-ratio", "--kernel-variant"};
    return flags;
}

IntegratorToggles parseToggles(const Options& o) {
    IntegratorToggles t;
    for (const ToggleRow& row : toggleTable()) {
        const bool on = *row.onFlag && o.has(row.onFlag), off = *row.offFlag && o.has(row.offFlag);
        if (on && off)
            throw UsageError(std::string(row.onFlag) + " and " + row.offFlag + " exclude each other");
        if (on || off) row.set(t, on);
    }
    // Naming a schedule turns the auto schedule off.
    const ToggleRow& schedule = toggleRow(ToggleId::Megakernel);
    t.autoSchedule = !o.has(schedule.onFlag) && !o.has(schedule.offFlag);
    t.clampRadiance = float(o.positiveNumber("--clamp").value_or(0.0));
    t.kernelVariant = o.value("--kernel-variant").value_or("");
    if (const auto ratio = o.positiveNumber("--rebuild-ratio")) {
        if (*ratio < 1.0) throw UsageError("--rebuild-ratio must be at least 1");
        t.rebuildSahRatio = float(*ratio);
    }
    return t;
}

nlohmann::ordered_json toggleStatesJson(const std::vector<ToggleState>& states) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (const ToggleState& s : states) {
        nlohmann::ordered_json entry;
        entry["on"] = s.requested;
        if (s.requested != s.active) entry["active"] = s.active;
        if (!s.note.empty()) entry["note"] = s.note;
        j[s.name] = entry;
    }
    return j;
}

std::set<std::string> joined(std::set<std::string> a, const std::set<std::string>& b) {
    a.insert(b.begin(), b.end());
    return a;
}

}  // namespace pt::cli
