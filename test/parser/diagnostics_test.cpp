// Diagnostics: each distinct warning printed once, repeats counted and summarised, output
// always printable.
#include "core/parser/diagnostics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <sstream>

namespace kiln {
namespace {

int Lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

TEST(Diagnostics, RepeatedWarningsArePrintedOnceAndCounted) {
    std::ostringstream out;
    Diagnostics diag(&out);
    auto file = std::make_shared<const std::string>("hair.pbrt");
    for (int i = 1; i <= 1000; ++i)
        diag.Warn(FileLoc(file, i, 1), "shape \"curve\" is not supported; skipped");
    diag.Warn(FileLoc(file, 5, 1), "another");
    EXPECT_EQ(Lines(out.str()), 2);
    EXPECT_NE(out.str().find("hair.pbrt:1:1: warning: shape \"curve\""), std::string::npos);
    EXPECT_EQ(diag.WarningCount(), 1001);
    EXPECT_EQ(diag.Warnings().size(), size_t(Diagnostics::kKeptPerMessage + 1));

    diag.ReportRepeats();
    EXPECT_EQ(Lines(out.str()), 3);
    EXPECT_NE(out.str().find("warning: shape \"curve\" is not supported; skipped (1000 times in "
                             "all)"),
              std::string::npos)
        << out.str();
    diag.ReportRepeats();  // nothing new to report
    EXPECT_EQ(Lines(out.str()), 3);
}

TEST(Diagnostics, MessagesAreMadePrintable) {
    std::string s = FormatDiagnostic(FileLoc(), "error", "bad \x1b[2J name", "\x01\x02tok");
    EXPECT_EQ(s, "error: bad \\x1b[2J name (at '\\x01\\x02tok')");
}

}  // namespace
}  // namespace kiln
