// Tokenizer for pbrt-v4 scene files.
//
// The whole file is held in memory and tokens are string_views into it, so large meshes
// tokenize without allocation. Token kinds follow pbrt-v4: bare words (directives, numbers,
// true/false), quoted strings (escapes \b \f \n \r \t \\ \' \" decoded; a string may not span
// lines), and the brackets [ ]. A bare word ends at whitespace, a quote or a bracket. `#`
// starts a comment up to the end of the line. A UTF-8 byte-order mark is skipped; UTF-16
// input is rejected.
#pragma once

#include "base/file_reading.h"

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "base/vecmath.h"
#include "core/parser/file_loc.h"

namespace kiln {

enum class TokenKind : uint8_t { Word, String, OpenBracket, CloseBracket };

struct Token {
    TokenKind kind = TokenKind::Word;
    // Word: as written; String: the contents, escapes decoded; brackets: "[" or "]".
    std::string_view text;
    // Exactly as written in the file (strings keep their quotes); used in error messages.
    std::string_view raw;
    int line = 0;
    int column = 0;

    bool IsWord(std::string_view w) const { return kind == TokenKind::Word && text == w; }
};

class Tokenizer {
  public:
    // `filename` is what FileLocs report.
    Tokenizer(std::string contents, std::string filename);
    Tokenizer(const Tokenizer&) = delete;
    Tokenizer& operator=(const Tokenizer&) = delete;

    // The next token, or nullopt at the end of the input. Throws SceneError on a malformed
    // string (unterminated, bad escape). Returned views stay valid while the Tokenizer lives.
    std::optional<Token> Next();

    FileLoc Loc(const Token& token) const { return FileLoc(filename_, token.line, token.column); }
    // The position just past the last character, for "unexpected end of file" errors.
    FileLoc EndLoc() const;
    const std::string& Filename() const { return *filename_; }

  private:
    [[noreturn]] void Fail(int line, int column, std::string message, std::string_view token);

    std::shared_ptr<const std::string> filename_;
    std::string contents_;
    const char* pos_;
    const char* end_;
    const char* lineStart_;
    int line_ = 1;
    std::deque<std::string> decoded_;  // Storage for strings that contained escapes.
};

// Reads a whole scene file (ReadFileBytes: regular files only, gzip decompressed); on failure
// returns false and sets *error to the reason.
bool ReadFileContents(const std::string& filename, std::string* contents, std::string* error,
                      uint64_t maxBytes = DefaultMaxInputBytes());

// Number parsing (pbrt-v4 syntax: optional sign, digits, optional fraction and exponent; the
// whole word must be consumed). Return false if `word` is not a valid number in range.
bool ParseFloat(std::string_view word, Float* value);
bool ParseInt(std::string_view word, int* value);

}  // namespace kiln
