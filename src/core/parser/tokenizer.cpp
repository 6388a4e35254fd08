#include "core/parser/tokenizer.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "base/file_reading.h"
#include "core/parser/diagnostics.h"

namespace kiln {

namespace {

bool IsSpace(char c) {
    return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

bool EndsWord(char c) { return IsSpace(c) || c == '"' || c == '[' || c == ']'; }

// Decodes the character after a backslash; returns -1 for an unknown escape.
int DecodeEscape(char c) {
    switch (c) {
        case 'b':
            return '\b';
        case 'f':
            return '\f';
        case 'n':
            return '\n';
        case 'r':
            return '\r';
        case 't':
            return '\t';
        case '\\':
            return '\\';
        case '\'':
            return '\'';
        case '"':
            return '"';
        default:
            return -1;
    }
}

}  // namespace

// Tokenizer
Tokenizer::Tokenizer(std::string contents, std::string filename)
    : filename_(std::make_shared<const std::string>(std::move(filename))),
      contents_(std::move(contents)) {
    pos_ = contents_.data();
    end_ = pos_ + contents_.size();
    lineStart_ = pos_;
    const auto* c = reinterpret_cast<const unsigned char*>(pos_);
    if (contents_.size() >= 2 && ((c[0] == 0xfe && c[1] == 0xff) || (c[0] == 0xff && c[1] == 0xfe)))
        Fail(1, 1, "file is encoded as UTF-16; scene files must be ASCII or UTF-8", "");
    if (contents_.size() >= 3 && c[0] == 0xef && c[1] == 0xbb && c[2] == 0xbf) {
        pos_ += 3;  // UTF-8 byte-order mark.
        lineStart_ = pos_;
    }
}

void Tokenizer::Fail(int line, int column, std::string message, std::string_view token) {
    throw SceneError(FileLoc(filename_, line, column), std::move(message), token);
}

FileLoc Tokenizer::EndLoc() const {
    int line = line_;
    const char* start = lineStart_;
    for (const char* p = pos_; p < end_; ++p)
        if (*p == '\n') {
            ++line;
            start = p + 1;
        }
    return FileLoc(filename_, line, int(end_ - start) + 1);
}

std::optional<Token> Tokenizer::Next() {
    while (pos_ < end_) {
        char c = *pos_;
        // Whitespace and comments
        if (c == '\n') {
            ++pos_;
            ++line_;
            lineStart_ = pos_;
            continue;
        }
        if (IsSpace(c)) {
            ++pos_;
            continue;
        }
        if (c == '#') {
            while (pos_ < end_ && *pos_ != '\n') ++pos_;
            continue;
        }

        Token tok;
        tok.line = line_;
        tok.column = int(pos_ - lineStart_) + 1;
        const char* start = pos_;

        // Brackets
        if (c == '[' || c == ']') {
            ++pos_;
            tok.kind = c == '[' ? TokenKind::OpenBracket : TokenKind::CloseBracket;
            tok.text = tok.raw = std::string_view(start, 1);
            return tok;
        }

        // Quoted strings
        if (c == '"') {
            tok.kind = TokenKind::String;
            const char* p = start + 1;
            bool escaped = false;
            while (p < end_ && *p != '"' && *p != '\n') {
                if (*p == '\\') {
                    escaped = true;
                    if (p + 1 < end_ && p[1] != '\n') ++p;
                }
                ++p;
            }
            if (p >= end_ || *p != '"') {
                const char* eol = p;
                if (eol > start && eol[-1] == '\r') --eol;
                Fail(tok.line, tok.column, "unterminated string",
                     std::string_view(start, eol - start));
            }
            pos_ = p + 1;
            tok.raw = std::string_view(start, pos_ - start);
            std::string_view body(start + 1, p - start - 1);
            if (!escaped) {
                tok.text = body;
                return tok;
            }
            std::string decoded;
            decoded.reserve(body.size());
            for (size_t i = 0; i < body.size(); ++i) {
                if (body[i] != '\\') {
                    decoded.push_back(body[i]);
                    continue;
                }
                int d = i + 1 < body.size() ? DecodeEscape(body[i + 1]) : -1;
                if (d < 0) {
                    int col = tok.column + 1 + int(i);
                    Fail(tok.line, col, "unknown escape sequence in string",
                         body.substr(i, i + 1 < body.size() ? 2 : 1));
                }
                decoded.push_back(char(d));
                ++i;
            }
            decoded_.push_back(std::move(decoded));
            tok.text = decoded_.back();
            return tok;
        }

        // Bare words: directives, numbers, true/false
        while (pos_ < end_ && !EndsWord(*pos_)) ++pos_;
        tok.kind = TokenKind::Word;
        tok.text = tok.raw = std::string_view(start, pos_ - start);
        return tok;
    }
    return std::nullopt;
}

// Files
bool ReadFileContents(const std::string& filename, std::string* contents, std::string* error,
                      uint64_t maxBytes) {
    return ReadFileBytes(filename, contents, error, maxBytes);
}

// Numbers
bool ParseFloat(std::string_view word, Float* value) {
    const char* first = word.data();
    const char* last = first + word.size();
    if (first != last && *first == '+') {
        ++first;  // from_chars rejects a leading '+'.
        if (first != last && *first == '-') return false;
    }
    const char* digits = (first != last && *first == '-') ? first + 1 : first;
    // Require a digit or '.', which rules out inf, nan and hex forms.
    if (digits == last || !((*digits >= '0' && *digits <= '9') || *digits == '.')) return false;
    auto [ptr, ec] = std::from_chars(first, last, *value);
    if (ptr != last) return false;
    if (ec == std::errc::result_out_of_range) {
        // Underflow rounds to zero or a denormal; overflow is an error.
        double d;
        auto r = std::from_chars(first, last, d);
        if (r.ec != std::errc() || std::abs(d) > double(std::numeric_limits<Float>::max()))
            return false;
        *value = Float(d);
        return true;
    }
    return ec == std::errc();
}

bool ParseInt(std::string_view word, int* value) {
    const char* first = word.data();
    const char* last = first + word.size();
    if (first != last && *first == '+') {
        ++first;
        if (first != last && *first == '-') return false;
    }
    auto [ptr, ec] = std::from_chars(first, last, *value);
    return ec == std::errc() && ptr == last;
}

}  // namespace kiln
