#include "core/parser/diagnostics.h"

#include <algorithm>
#include <iostream>

namespace kiln {

std::string Printable(std::string_view text, size_t maxBytes) {
    std::string s;
    for (size_t i = 0; i < text.size(); ++i) {
        if (s.size() >= maxBytes) {
            s += "... (" + std::to_string(text.size()) + " bytes)";
            break;
        }
        unsigned char c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7f) {
            s += char(c);
        } else {
            static const char* hex = "0123456789abcdef";
            s += "\\x";
            s += hex[c >> 4];
            s += hex[c & 15];
        }
    }
    return s;
}

std::string FormatDiagnostic(const FileLoc& loc, std::string_view severity,
                             std::string_view message, std::string_view token) {
    std::string s = Printable(loc.ToString(), 4096);
    if (!s.empty()) s += ": ";
    s += severity;
    s += ": ";
    s += Printable(message, 4096);
    if (!token.empty()) {
        s += " (at '";
        s += Printable(token, 80);
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
    ++total_;
    auto [it, first] = tallies_.try_emplace(message);
    Tally& t = it->second;
    if (first) t.order = tallies_.size();
    if (++t.count == 1 && out_) *out_ << FormatDiagnostic(loc, "warning", message) << '\n';
    if (t.count <= kKeptPerMessage) warnings_.push_back({loc, std::move(message)});
}

void Diagnostics::ReportRepeats() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::pair<size_t, const std::string*>> repeated;
    for (auto& [message, t] : tallies_)
        if (t.count > 1 && t.count != t.reported) repeated.push_back({t.order, &message});
    std::sort(repeated.begin(), repeated.end());
    for (auto [order, message] : repeated) {
        Tally& t = tallies_[*message];
        if (out_)
            *out_ << FormatDiagnostic(FileLoc(), "warning",
                                      *message + " (" + std::to_string(t.count) + " times in all)")
                  << '\n';
        t.reported = t.count;
    }
}

int Diagnostics::WarningCount() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return total_;
}

std::vector<Diagnostics::Warning> Diagnostics::Warnings() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return warnings_;
}

}  // namespace kiln
