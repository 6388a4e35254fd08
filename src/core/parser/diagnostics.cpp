#include "core/parser/diagnostics.h"

#include <iostream>

namespace kiln {

std::string FormatDiagnostic(const FileLoc& loc, std::string_view severity,
                             std::string_view message, std::string_view token) {
    std::string s = loc.ToString();
    if (!s.empty()) s += ": ";
    s += severity;
    s += ": ";
    s += message;
    if (!token.empty()) {
        s += " (at '";
        s += token;
        s += "')";
    }
    return s;
}

// SceneError
SceneError::SceneError(const FileLoc& loc, std::string message, std::string_view token)
    : std::runtime_error(FormatDiagnostic(loc, "error", message, token)),
      loc_(loc),
      message_(std::move(message)),
      token_(token) {}

// Diagnostics
Diagnostics::Diagnostics(std::ostream* out) : out_(out) {}
Diagnostics::Diagnostics() : out_(&std::cerr) {}

void Diagnostics::SetOutput(std::ostream* out) {
    std::lock_guard<std::mutex> lock(mutex_);
    out_ = out;
}

void Diagnostics::Warn(const FileLoc& loc, std::string message) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (out_) *out_ << FormatDiagnostic(loc, "warning", message) << '\n';
    warnings_.push_back({loc, std::move(message)});
}

int Diagnostics::WarningCount() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return int(warnings_.size());
}

std::vector<Diagnostics::Warning> Diagnostics::Warnings() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return warnings_;
}

}  // namespace kiln
