// MemoryBudget (base/memory_budget.h): sizes as users write them, and charges that stop
// at the limit with a message naming what and how much.
#include <gtest/gtest.h>

#include <cmath>

#include "base/memory_budget.h"

namespace kiln {
namespace {

TEST(MemoryBudget, ParsesSizes) {
    EXPECT_EQ(MemoryBudget::ParseSize("800000"), 800000.0);
    EXPECT_EQ(MemoryBudget::ParseSize("2G"), 2e9);
    EXPECT_EQ(MemoryBudget::ParseSize("512M"), 512e6);
    EXPECT_EQ(MemoryBudget::ParseSize("1.5GB"), 1.5e9);
    EXPECT_EQ(MemoryBudget::ParseSize("64 MiB"), 64.0 * 1024 * 1024);
    EXPECT_EQ(MemoryBudget::ParseSize("2k"), 2000.0);
    EXPECT_EQ(MemoryBudget::ParseSize("1TiB"), 1024.0 * 1024 * 1024 * 1024);
    for (const char* bad : {"", "G", "-1G", "0", "3Q", "2GG", "nan", "inf", "1e400"})
        EXPECT_FALSE(MemoryBudget::ParseSize(bad).has_value()) << bad;
}

TEST(MemoryBudget, ChargesStopAtTheLimit) {
    MemoryBudget budget(1000);
    EXPECT_TRUE(budget.Explicit());
    budget.Charge(600, "a film");
    EXPECT_EQ(budget.Committed(), 600);
    EXPECT_EQ(budget.Remaining(), 400);
    try {
        budget.Charge(500, "a mesh of 3 triangles");
        ADD_FAILURE() << "no error";
    } catch (const MemoryLimitError& e) {
        std::string m = e.what();
        EXPECT_NE(m.find("a mesh of 3 triangles needs 500 bytes"), std::string::npos) << m;
        EXPECT_NE(m.find("600 bytes already committed"), std::string::npos) << m;
        EXPECT_NE(m.find("--memory-limit"), std::string::npos) << m;
    }
    EXPECT_EQ(budget.Committed(), 600);  // a refused charge takes nothing
    budget.Charge(400, "the rest");
    // An estimate that overflowed counts as too much
    EXPECT_THROW(budget.Charge(std::nan(""), "nothing known"), MemoryLimitError);
    // Without a limit of its own, the machine's memory
    MemoryBudget machine;
    EXPECT_FALSE(machine.Explicit());
    EXPECT_THROW(machine.Charge(1e30, "an absurd film"), MemoryLimitError);
}

}  // namespace
}  // namespace kiln
