#include "cli/display_options.h"

#include <cmath>

#include "assets/color/color_config.h"

namespace pt::cli {

namespace {

// The flags that choose an OpenColorIO view.
constexpr const char* kOcioFlags[] = {"--ocio", "--display", "--view", "--look"};

float parseStops(const std::string& text) {
    size_t used = 0;
    double stops = 0.0;
    try {
        stops = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || !std::isfinite(stops) || std::fabs(stops) > 64.0) {
        throw UsageError("--exposure: expected stops in [-64, 64], got \"" + text + "\"");
    }
    return float(stops);
}

}  // namespace

const std::set<std::string>& displayValuedFlags() {
    static const std::set<std::string> flags = {"--ocio",    "--display",     "--view",    "--look",
                                                "--tonemap", "--white-point", "--exposure"};
    return flags;
}

const std::set<std::string>& displaySwitches() {
    static const std::set<std::string> switches = {"--no-dither"};
    return switches;
}

DisplayRequest parseDisplayOptions(const Options& o) {
    DisplayRequest r;
    for (const std::string& flag : displayValuedFlags()) r.anyGiven = r.anyGiven || o.has(flag);
    r.anyGiven = r.anyGiven || o.has("--no-dither");
    r.ocioConfig = o.value("--ocio").value_or("");
    r.view.display = o.value("--display").value_or("");
    r.view.view = o.value("--view").value_or("");
    r.view.look = o.value("--look").value_or("");
    if (const std::optional<std::string> name = o.value("--tonemap")) {
        ToneMapper op = ToneMapper::Clamp;
        if (!parseToneMapper(*name, op)) {
            throw UsageError("--tonemap: unknown operator \"" + *name +
                             "\" (standard, reinhard, aces-fitted, agx)");
        }
        r.toneMapper = op;
        for (const char* flag : kOcioFlags) {
            if (o.has(flag)) throw UsageError(std::string("--tonemap and ") + flag + " exclude each other");
        }
    }
    if (const std::optional<double> white = o.positiveNumber("--white-point")) {
        if (r.toneMapper != ToneMapper::Reinhard) throw UsageError("--white-point needs --tonemap reinhard");
        r.whitePoint = float(*white);
    }
    if (const std::optional<std::string> stops = o.value("--exposure")) r.exposureStops = parseStops(*stops);
    r.dither = !o.has("--no-dither");
#if !defined(PT_HAVE_OCIO)
    for (const char* flag : kOcioFlags) {
        if (o.has(flag))
            throw UsageError(std::string(flag) +
                             ": this build has no OpenColorIO (PT_OCIO=OFF); use --tonemap");
    }
#endif
    return r;
}

DisplayProcessor makeDisplayProcessor(const DisplayRequest& request, const ColorSettings& scene) {
#if defined(PT_HAVE_OCIO)
    if (!request.toneMapper) {
        const std::string path = resolveColorConfigPath(request.ocioConfig, scene.config);
        const std::shared_ptr<const ColorConfig> config = ColorConfig::load(path);
        // The scene's names belong to the scene's config; another one (--ocio) starts afresh.
        ViewTransform wanted = request.ocioConfig.empty()
                                   ? ViewTransform{scene.display, scene.view, scene.look}
                                   : ViewTransform{};
        if (!request.view.display.empty()) wanted.display = request.view.display;
        if (!request.view.view.empty()) wanted.view = request.view.view;
        if (!request.view.look.empty()) wanted.look = request.view.look;
        return DisplayProcessor(*config, config->resolve(wanted), request.exposureStops);
    }
#else
    (void)scene;
#endif
    DisplaySettings builtin;
    builtin.exposureStops = request.exposureStops;
    builtin.toneMapper = request.toneMapper.value_or(ToneMapper::Clamp);
    builtin.whitePoint = request.whitePoint;
    builtin.dither = request.dither;
    return DisplayProcessor(builtin);
}

}  // namespace pt::cli
