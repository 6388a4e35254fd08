// Parser: malformed input throws SceneError with file:line:column and the offending token.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "core/parser/parser.h"
#include "recording_target.h"

namespace kiln {

namespace {

// The SceneError's what() for `text`, or "no error".
std::string ErrorOf(std::string_view text, const std::string& searchDirectory = "") {
    RecordingTarget target;
    Diagnostics diag(nullptr);
    try {
        ParseString(target, text, diag, "bad.pbrt", searchDirectory);
    } catch (const SceneError& e) {
        EXPECT_EQ(target.endOfFiles, 0);
        return e.what();
    }
    return "no error";
}

struct Case {
    const char* input;
    const char* expected;
};

}  // namespace

TEST(ParserErrors, MalformedInput) {
    const Case cases[] = {
        {"Shape \"sphere\"\n  Bogus 1", "bad.pbrt:2:3: error: unknown directive (at 'Bogus')"},
        {"Translate 1 x 3",
         "bad.pbrt:1:13: error: expected a number as argument of Translate (at 'x')"},
        {"Transform [1 2 3]", "bad.pbrt:1:17: error: Transform needs 16 numbers (at ']')"},
        {"ConcatTransform 1 0 0 0",
         "bad.pbrt:1:17: error: expected '[' in ConcatTransform (at '1')"},
        {"Shape \"sphere\n\"float radius\" 1",
         "bad.pbrt:1:7: error: unterminated string (at '\"sphere')"},
        {"Shape \"s\"\n\t\"float a\" [1 2",
         "bad.pbrt:2:12: error: unbalanced '[': no matching ']' before the end of file (at '[')"},
        {"Shape \"s\" \"float a\" 1 ]", "bad.pbrt:1:23: error: unexpected ']' (at ']')"},
        {"Shape \"s\" \"float a\" [1 2x]",
         "bad.pbrt:1:24: error: expected a number for float parameter 'a' (at '2x')"},
        {"Shape \"s\" \"floaty a\" 1",
         "bad.pbrt:1:11: error: unknown parameter type 'floaty' (at '\"floaty a\"')"},
        {"Shape \"s\" \"point2 uv\" [1 2 3]",
         "bad.pbrt:1:11: error: point2 parameter 'uv' has 3 values, not a multiple of 2 (at "
         "'\"point2 uv\"')"},
        {"Material \"m\" \"spectrum eta\" [300 1.5 400]",
         "bad.pbrt:1:14: error: odd number of values (3) for spectrum wavelength/value pairs "
         "(at '\"spectrum eta\"')"},
        {"Material \"m\" \"color Kd\" [.5 .5]",
         "bad.pbrt:1:14: error: rgb parameter 'Kd' has 2 values, not a multiple of 3 (at "
         "'\"color Kd\"')"},
        {"Shape \"s\" \"bool b\" 1",
         "bad.pbrt:1:20: error: expected true or false for bool parameter 'b' (at '1')"},
        {"Shape \"s\" \"string f\" [ foo ]",
         "bad.pbrt:1:24: error: expected a quoted string for string parameter 'f' (at 'foo')"},
        {"Shape \"s\" \"float\" 1",
         "bad.pbrt:1:11: error: parameter declaration must be \"type name\" (at '\"float\"')"},
        {"Shape \"s\" \"string f\" \"a\\qb\"",
         "bad.pbrt:1:24: error: unknown escape sequence in string (at '\\q')"},
        {"ActiveTransform Sometimes",
         "bad.pbrt:1:17: error: ActiveTransform expects All, StartTime or EndTime (at "
         "'Sometimes')"},
        {"WorldBegin\nImport",
         "bad.pbrt:2:7: error: unexpected end of file in the arguments "
         "of Import (at bad.pbrt:2:1)"},
        {"Import \"x.pbrt\"",
         "bad.pbrt:1:1: error: Import is only allowed after WorldBegin (use Include) (at "
         "'Import')"},
        {"Translate 1 2 3\n  4 5",
         "bad.pbrt:2:3: error: unexpected value: values must follow "
         "a \"type name\" parameter declaration (at '4')"},
        {"Camera perspective",
         "bad.pbrt:1:8: error: Camera expects a quoted string (name) (at "
         "'perspective')"},
        {"\"float fov\" 45",
         "bad.pbrt:1:1: error: unexpected string: a parameter list must follow a directive (at "
         "'\"float fov\"')"},
        {"LightSource \"l\" \"spectrum L\" [300 1 \"stdillum-D65\"]",
         "bad.pbrt:1:37: error: spectrum parameter 'L' mixes numbers and strings (at "
         "'\"stdillum-D65\"')"},
        {"Shape \"s\" \"integer n\" \"3\"",
         "bad.pbrt:1:23: error: expected an integer for parameter 'n' (at '\"3\"')"},
        {"Scale 1 1 1e999",
         "bad.pbrt:1:11: error: expected a number as argument of Scale (at "
         "'1e999')"},
        {"Shape \"s\" \"float a\" [ 1 [ 2 ] ]",
         "bad.pbrt:1:25: error: unexpected '[' in a list (at '[')"},
    };
    for (const Case& c : cases) EXPECT_EQ(ErrorOf(c.input), c.expected) << c.input;
}

TEST(ParserErrors, IncludeProblems) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("kiln_parser_inc_" + std::to_string(getpid()));
    fs::create_directories(dir / "sub");
    std::ofstream(dir / "sub/a.pbrt") << "Translate 1 2 3\n  Include \"sub/b.pbrt\"\n";
    std::ofstream(dir / "sub/b.pbrt") << "Include \"sub/a.pbrt\"\n";
    std::ofstream(dir / "sub/c.pbrt") << "Scale 1 1 1\n   Shape \"x\" \"float r\" [ oops ]\n";
    std::string d = dir.string();

    EXPECT_EQ(ErrorOf("\n Include \"missing.pbrt\"", d),
              "bad.pbrt:2:10: error: cannot open 'missing.pbrt': No such file or directory (at "
              "'\"missing.pbrt\"')");
    // A cycle a -> b -> a, reported in b where it closes.
    EXPECT_EQ(ErrorOf("Include \"sub/a.pbrt\"", d),
              (dir / "sub/b.pbrt").string() +
                  ":1:9: error: 'sub/a.pbrt' includes itself (directly or not) (at "
                  "'\"sub/a.pbrt\"')");
    // Errors inside an included file carry that file's name.
    EXPECT_EQ(ErrorOf("Include \"sub/c.pbrt\"", d),
              (dir / "sub/c.pbrt").string() +
                  ":2:26: error: expected a number for float parameter 'r' (at 'oops')");
    // Importing a file that imports itself.
    std::ofstream(dir / "sub/imp.pbrt") << "Import \"sub/imp.pbrt\"\n";
    EXPECT_EQ(ErrorOf("WorldBegin Import \"sub/imp.pbrt\"", d),
              (dir / "sub/imp.pbrt").string() +
                  ":1:8: error: 'sub/imp.pbrt' includes itself (directly or not) (at "
                  "'\"sub/imp.pbrt\"')");
    fs::remove_all(dir);
}

TEST(ParserErrors, MissingSceneFile) {
    RecordingTarget target;
    Diagnostics diag(nullptr);
    try {
        ParseFile(target, "/nonexistent/scene.pbrt", diag);
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "/nonexistent/scene.pbrt: error: cannot open scene file: No such file or "
                  "directory");
    }
}

}  // namespace kiln
