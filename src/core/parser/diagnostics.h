// Diagnostics (collected warnings) and SceneError (fatal scene-description errors).
//
// Errors in a scene description are thrown as SceneError, whose what() reads
//   file:line:column: error: <message> (at 'offending token')
// Turning one into an exit code is the caller's job. Warnings do not stop parsing: they are
// collected by a Diagnostics object that the caller owns and passes down.
#pragma once

#include <iosfwd>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/parser/file_loc.h"

namespace kiln {

// SceneError
class SceneError : public std::runtime_error {
  public:
    // `token` is the offending text as written in the file; empty omits the "(at ...)" part.
    SceneError(const FileLoc& loc, std::string message, std::string_view token = {});

    const FileLoc& Loc() const { return loc_; }
    const std::string& Message() const { return message_; }
    const std::string& Token() const { return token_; }

  private:
    FileLoc loc_;
    std::string message_;
    std::string token_;
};

// Text safe for a terminal: bytes outside printable ASCII as \xNN, cut after maxBytes with
// the full length noted.
std::string Printable(std::string_view text, size_t maxBytes);

// "file:line:column: <severity>: <message>[ (at 'token')]", omitting unknown parts; every
// part through Printable (the token cut at 80 bytes), so binary input never reaches a terminal.
std::string FormatDiagnostic(const FileLoc& loc, std::string_view severity,
                             std::string_view message, std::string_view token = {});

// Diagnostics
class Diagnostics {
  public:
    struct Warning {
        FileLoc loc;
        std::string message;
    };

    // Warnings are printed to `out` as they arrive (stderr by default; nullptr = silent).
    explicit Diagnostics(std::ostream* out);
    Diagnostics();
    Diagnostics(const Diagnostics&) = delete;
    Diagnostics& operator=(const Diagnostics&) = delete;

    void SetOutput(std::ostream* out);

    // Thread-safe: scene objects may be created in parallel. Each distinct message is printed
    // the first time only (a hair file can repeat one warning a million times) and kept, with
    // its location, up to kKeptPerMessage times; ReportRepeats prints how often each recurred.
    void Warn(const FileLoc& loc, std::string message);
    void Warn(std::string message) { Warn(FileLoc(), std::move(message)); }

    // Prints "warning: <message> (N times in all)" for every message given more than once
    // since the last call, in the order they first came.
    void ReportRepeats();

    // Every warning given, repeats included.
    int WarningCount() const;
    // The warnings kept (see Warn).
    std::vector<Warning> Warnings() const;

    static constexpr int kKeptPerMessage = 100;

  private:
    struct Tally {
        int count = 0, reported = 0;
        size_t order = 0;
    };
    mutable std::mutex mutex_;
    std::ostream* out_;
    std::vector<Warning> warnings_;
    std::unordered_map<std::string, Tally> tallies_;
    int total_ = 0;
};

}  // namespace kiln
