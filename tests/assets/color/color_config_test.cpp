// OpenColorIO configs: the shipped config (valid, its built-in transform names known to the
// installed library, the displays / views / looks the editor lists), which config is chosen,
// and the errors for bad configs and unknown names.
#if defined(PT_HAVE_OCIO)
#include "assets/color/color_config.h"

#include <OpenColorIO/OpenColorIO.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include "assets/input_error.h"
#include "assets/scene_test_helpers.h"
#include "support/input_error_of.h"
#include "support/test_paths.h"

namespace pt {
namespace {

using test::inputErrorOf;

namespace OCIO = OCIO_NAMESPACE;
using Names = std::vector<std::string>;

std::string shippedConfig() { return test::projectPath("scenes/ocio/config.ocio"); }

// Sets an environment variable for the life of the object, then restores it.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value) {
            setenv(name, value, 1);
        } else {
            unsetenv(name);
        }
    }
    ~ScopedEnv() {
        if (old_) {
            setenv(name_, old_->c_str(), 1);
        } else {
            unsetenv(name_);
        }
    }

private:
    const char* name_;
    std::optional<std::string> old_;
};

TEST(ColorConfig, ShippedConfigIsValidAndOffersItsDisplaysViewsAndLooks) {
    const auto config = ColorConfig::load(shippedConfig());
    EXPECT_EQ(config->path(), shippedConfig());
    EXPECT_EQ(config->displays(), (Names{"sRGB", "Rec.1886"}));
    for (const std::string& display : config->displays()) {
        EXPECT_EQ(config->views(display), (Names{"Standard", "AgX", "ACES 1.0 SDR", "Raw"})) << display;
    }
    EXPECT_EQ(config->looks(), (Names{"Exposure +1", "Exposure -1"}));
    EXPECT_EQ(config->defaultDisplay(), "sRGB");
    EXPECT_EQ(config->defaultView("sRGB"), "Standard")
        << "PNG output keeps its plain sRGB meaning by default";
    EXPECT_TRUE(config->views("no such display").empty());

    // And straight through OpenColorIO: the version asked for, and validate().
    const OCIO::ConstConfigRcPtr raw = OCIO::Config::CreateFromFile(shippedConfig().c_str());
    EXPECT_EQ(raw->getMajorVersion(), 2u);
    EXPECT_EQ(raw->getMinorVersion(), 1u);
    EXPECT_NO_THROW(raw->validate());
    EXPECT_STREQ(raw->getColorSpace(OCIO::ROLE_SCENE_LINEAR)->getName(), "Linear Rec.709 (sRGB)");
}

TEST(ColorConfig, EveryBuiltinTransformStyleExistsInTheInstalledLibrary) {
    std::ifstream in(shippedConfig());
    std::stringstream text;
    text << in.rdbuf();
    const std::string config = text.str();
    const OCIO::ConstBuiltinTransformRegistryRcPtr registry = OCIO::BuiltinTransformRegistry::Get();
    std::set<std::string> known;
    for (size_t i = 0; i < registry->getNumBuiltins(); ++i) known.insert(registry->getBuiltinStyle(i));
    const std::regex style(R"(!<BuiltinTransform>\s*\{\s*style:\s*([^,}\n]+?)\s*[,}])");
    size_t count = 0;
    for (auto it = std::sregex_iterator(config.begin(), config.end(), style); it != std::sregex_iterator();
         ++it) {
        const std::string name = (*it)[1];
        EXPECT_TRUE(known.count(name))
            << "\"" << name << "\" is not a built-in transform of OpenColorIO " << OCIO::GetVersion();
        ++count;
    }
    EXPECT_GE(count, 6u) << "the style pattern no longer matches the config's BuiltinTransforms";
}

TEST(ColorConfig, ShippedConfigIsFoundFromTheSourceTreeOrPtSourceDir) {
    {
        const ScopedEnv unset("PT_SOURCE_DIR", nullptr);
        EXPECT_TRUE(std::filesystem::is_regular_file(shippedColorConfigPath())) << shippedColorConfigPath();
    }
    const ScopedEnv moved("PT_SOURCE_DIR", "/elsewhere/project");
    EXPECT_EQ(shippedColorConfigPath(), "/elsewhere/project/scenes/ocio/config.ocio");
}

TEST(ColorConfig, ResolutionOrderIsFlagThenSceneThenEnvironmentThenShipped) {
    {
        const ScopedEnv env("OCIO", "/env/config.ocio");
        EXPECT_EQ(resolveColorConfigPath("/flag.ocio", "/scene.ocio"), "/flag.ocio");
        EXPECT_EQ(resolveColorConfigPath("", "/scene.ocio"), "/scene.ocio");
        EXPECT_EQ(resolveColorConfigPath("", ""), "/env/config.ocio");
    }
    {
        const ScopedEnv empty("OCIO", "");
        EXPECT_EQ(resolveColorConfigPath("", ""), shippedColorConfigPath());
    }
    const ScopedEnv unset("OCIO", nullptr);
    EXPECT_EQ(resolveColorConfigPath("", ""), shippedColorConfigPath());
}

TEST(ColorConfig, BadConfigFilesAreInputErrorsNamingTheFile) {
    const std::string folder = test::testFolder();
    const std::string missing = folder + "/missing.ocio";
    EXPECT_NE(inputErrorOf([&] { ColorConfig::load(missing); }).find(missing), std::string::npos);

    const std::string garbage =
        test::writeFile(folder, "garbage.ocio", "ocio_profile_version: 2.1\nroles: [\n");
    const std::string message = inputErrorOf([&] { ColorConfig::load(garbage); });
    EXPECT_NE(message.find(garbage), std::string::npos) << message;
    EXPECT_GT(message.size(), garbage.size() + 10)
        << "OpenColorIO's own message follows the path: " << message;

    // Parses, but names a display colour space that does not exist: validate() refuses it.
    const std::string invalid = test::writeFile(folder, "invalid.ocio", R"(ocio_profile_version: 2.1
roles: {default: lin, scene_linear: lin}
file_rules: [!<Rule> {name: Default, colorspace: default}]
displays: {Screen: [!<View> {name: Plain, colorspace: nope}]}
colorspaces: [!<ColorSpace> {name: lin}]
)");
    const std::string invalidMessage = inputErrorOf([&] { ColorConfig::load(invalid); });
    EXPECT_NE(invalidMessage.find(invalid), std::string::npos) << invalidMessage;
    EXPECT_NE(invalidMessage.find("nope"), std::string::npos) << invalidMessage;
}

TEST(ColorConfig, ResolveFillsDefaultsAndNamesUnknownChoicesWithTheAlternatives) {
    const auto config = ColorConfig::load(shippedConfig());
    const ViewTransform defaults = config->resolve({});
    EXPECT_EQ(defaults.display, "sRGB");
    EXPECT_EQ(defaults.view, "Standard");
    EXPECT_EQ(defaults.look, "");
    const ViewTransform agx = config->resolve({"Rec.1886", "AgX", "Exposure -1"});
    EXPECT_EQ(agx.display, "Rec.1886");
    EXPECT_EQ(agx.view, "AgX");
    EXPECT_EQ(agx.look, "Exposure -1");
    EXPECT_EQ(config->resolve({"", "Raw", ""}).display, "sRGB");

    const std::string display = inputErrorOf([&] { config->resolve({"P3", "", ""}); });
    EXPECT_NE(display.find("\"P3\""), std::string::npos) << display;
    EXPECT_NE(display.find("\"Rec.1886\""), std::string::npos) << display;
    EXPECT_NE(display.find(shippedConfig()), std::string::npos) << display;
    const std::string view = inputErrorOf([&] { config->resolve({"sRGB", "Filmic", ""}); });
    EXPECT_NE(view.find("\"Filmic\""), std::string::npos) << view;
    EXPECT_NE(view.find("\"ACES 1.0 SDR\""), std::string::npos) << view;
    const std::string look = inputErrorOf([&] { config->resolve({"", "", "Punchy"}); });
    EXPECT_NE(look.find("\"Punchy\""), std::string::npos) << look;
    EXPECT_NE(look.find("\"Exposure +1\""), std::string::npos) << look;
}

}  // namespace
}  // namespace pt
#endif  // PT_HAVE_OCIO
