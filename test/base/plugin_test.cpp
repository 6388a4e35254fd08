// Plugins (base/plugin.h): the build's plugins load and export what kiln calls; a missing
// library or symbol is an error that names what was tried.
#include "base/plugin.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace kiln {
namespace {

TEST(Plugin, TheBuildsPluginsLoad) {
    EXPECT_NE(PluginSymbol("libkiln_oiio.so", "KilnOIIOImageCodec"), nullptr);
    EXPECT_NE(PluginSymbol("libkiln_oiio.so", "KilnOIIOColorMap"), nullptr);
    EXPECT_NE(PluginSymbol("libkiln_openvdb.so", "KilnOpenVDBFile"), nullptr);
    // Loaded once: the same address again
    EXPECT_EQ(PluginSymbol("libkiln_oiio.so", "KilnOIIOImageCodec"),
              PluginSymbol("libkiln_oiio.so", "KilnOIIOImageCodec"));
}

TEST(Plugin, MissingLibraryOrSymbolIsAClearError) {
    try {
        PluginSymbol("libkiln_nonexistent.so", "Anything");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        std::string what = e.what();
        EXPECT_NE(what.find("cannot load kiln's plugin libkiln_nonexistent.so"), std::string::npos)
            << what;
        EXPECT_NE(what.find(std::string(KILN_BINARY_DIR) + "/libkiln_nonexistent.so"),
                  std::string::npos)
            << what;
    }
    try {
        PluginSymbol("libkiln_oiio.so", "NoSuchFunction");
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("has no symbol NoSuchFunction"), std::string::npos);
    }
}

}  // namespace
}  // namespace kiln
