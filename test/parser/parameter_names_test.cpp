// The vocabulary of parameter names (core/parser/parameter_names.h): sorted and unique (it is
// searched by bisection), and holding every name kiln's source reads by a literal, so that no
// parameter kiln uses is ever refused as unknown.
#include "core/parser/parameter_names.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "core/parser/suggestions.h"

namespace kiln {
namespace {

TEST(ParameterNames, SortedAndUnique) {
    auto names = KnownParameterNames();
    EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
    EXPECT_GT(names.size(), 150u);
}

TEST(ParameterNames, EveryNameKilnReadsIsKnown) {
    // Lookups by literal name: GetOne*("x"), Get*Array("x"), Get*Texture*("x"), Has("x"), ...
    std::regex lookup(
        R"re(\b(GetOne\w*|Get\w*Array|Get\w*Texture\w*|Has|Loc|positive)\s*\(\s*"([A-Za-z0-9_.]+)")re");
    int checked = 0;
    for (const auto& e :
         std::filesystem::recursive_directory_iterator(std::string(KILN_SOURCE_DIR) + "/src")) {
        std::string ext = e.path().extension().string();
        if (ext != ".cpp" && ext != ".h") continue;
        std::ifstream in(e.path());
        std::stringstream text;
        text << in.rdbuf();
        std::string s = text.str();
        for (std::sregex_iterator it(s.begin(), s.end(), lookup), end; it != end; ++it) {
            std::string name = (*it)[2];
            EXPECT_TRUE(IsKnownParameterName(name)) << e.path() << " reads \"" << name << "\"";
            ++checked;
        }
    }
    EXPECT_GT(checked, 200);
}

TEST(Suggestions, NearestNameIsCloseOrNothing) {
    constexpr std::string_view names[] = {"sphere", "disk", "spot", "temperature"};
    EXPECT_EQ(NearestName("spheer", names), "sphere");
    EXPECT_EQ(NearestName("temprature", names), "temperature");
    EXPECT_EQ(NearestName("sp", names), std::nullopt);  // too short to guess
    EXPECT_EQ(NearestName("cylinder", names), std::nullopt);
    EXPECT_EQ(NearestName("disk", names), std::nullopt);  // itself
    EXPECT_EQ(EditDistance("kitten", "sitting"), 3u);
}

}  // namespace
}  // namespace kiln
