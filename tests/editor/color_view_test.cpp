// The editor's choice of OpenColorIO config and view: the scene's names resolved in the config,
// the config reused while its path stays, and clear reasons (never a throw) where the file or
// the view is wrong, with a view that still draws.
#include "editor/color_view.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace pt::editor {
namespace {

#ifdef PT_HAVE_OCIO

TEST(ColorView, ResolvesTheScenesViewInTheShippedConfig) {
    ColorSettings settings;
    settings.display = "sRGB";
    settings.view = "AgX";
    const ColorView view = resolveColorView(shippedColorConfigPath(), settings, {});
    ASSERT_TRUE(view.config) << view.error;
    EXPECT_EQ(view.error, "");
    EXPECT_EQ(view.view.display, "sRGB");
    EXPECT_EQ(view.view.view, "AgX");
    EXPECT_EQ(view.view.look, "");
    EXPECT_NE(view.key(), ColorView{}.key());

    // Another view of the same config: the loaded config is kept, the key changes.
    settings.view = "ACES 1.0 SDR";
    const ColorView next = resolveColorView(shippedColorConfigPath(), settings, view);
    EXPECT_EQ(next.config, view.config);
    EXPECT_NE(next.key(), view.key());
}

TEST(ColorView, AnUnknownViewFallsBackToTheDefaultAndSaysWhy) {
    ColorSettings settings;
    settings.view = "Filmic Very High Contrast";
    const ColorView view = resolveColorView(shippedColorConfigPath(), settings, {});
    ASSERT_TRUE(view.config);
    EXPECT_NE(view.error.find("Filmic Very High Contrast"), std::string::npos) << view.error;
    EXPECT_EQ(view.view.view, view.config->defaultView(view.view.display));
}

TEST(ColorView, ABrokenConfigLeavesTheBuiltInOperatorsAndNamesTheFile) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "pt_color_view_test_broken.ocio";
    std::ofstream(path) << "ocio_profile_version: 2.1\nroles: [this is not a map\n";
    const ColorView view = resolveColorView(path.string(), {}, {});
    EXPECT_FALSE(view.config);
    EXPECT_NE(view.error.find(path.string()), std::string::npos) << view.error;
    EXPECT_EQ(view.key(), "built-in");
}

#else

TEST(ColorView, WithoutOpenColorIOTheSceneChoiceIsReported) {
    ColorSettings settings;
    settings.view = "AgX";
    const ColorView view = resolveColorView("", settings, {});
    EXPECT_FALSE(view.config);
    EXPECT_NE(view.error.find("OpenColorIO"), std::string::npos);
}

#endif

}  // namespace
}  // namespace pt::editor
