#include "toggle_options.h"

namespace pt::cli {

const std::set<std::string>& toggleSwitches() {
    static const std::set<std::string> switches = {"--no-nee",
                                                   "--no-mis",
                                                   "--no-rr",
                                                   "--bvh-off",
                                                   "--no-merge",
                                                   "--no-jitter",
                                                   "--megakernel",
                                                   "--wavefront",
                                                   "--regeneration",
                                                   "--no-compaction",
                                                   "--sort-materials",
                                                   "--no-sort-materials",
                                                   "--no-first-hit-cache"};
    return switches;
}

const std::set<std::string>& toggleValuedFlags() {
    static const std::set<std::string> flags = {"--clamp", "--rebuild-ratio", "--kernel-variant"};
    return flags;
}

IntegratorToggles parseToggles(const Options& o) {
    IntegratorToggles t;
    t.nextEventEstimation = !o.has("--no-nee");
    t.multipleImportance = !o.has("--no-mis");
    t.russianRoulette = !o.has("--no-rr");
    t.bruteForce = o.has("--bvh-off");
    t.mergeInstances = !o.has("--no-merge");
    t.clampRadiance = float(o.positiveNumber("--clamp").value_or(0.0));
    t.pixelJitter = !o.has("--no-jitter");
    if (o.has("--megakernel") && o.has("--wavefront")) throw UsageError("--megakernel and --wavefront exclude each other");
    // Naming a schedule turns the auto schedule off.
    t.autoSchedule = !o.has("--megakernel") && !o.has("--wavefront");
    if (o.has("--megakernel")) t.megakernel = true;
    if (o.has("--wavefront")) t.megakernel = false;
    if (o.has("--regeneration")) t.pathRegeneration = true;
    if (o.has("--no-compaction")) t.streamCompaction = false;
    if (o.has("--sort-materials") && o.has("--no-sort-materials")) {
        throw UsageError("--sort-materials and --no-sort-materials exclude each other");
    }
    if (o.has("--sort-materials")) t.materialSort = true;
    if (o.has("--no-sort-materials")) t.materialSort = false;
    if (o.has("--no-first-hit-cache")) t.firstHitCache = false;
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
