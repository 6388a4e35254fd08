#include "base/memory_budget.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "base/system_memory.h"

namespace kiln {

void MemoryBudget::SetLimit(double limitBytes) {
    explicitLimit = limitBytes > 0;
    limit = explicitLimit ? limitBytes : PhysicalMemoryBytes();
}

double MemoryBudget::Committed() const {
    std::lock_guard<std::mutex> lock(mutex);
    return committed;
}

double MemoryBudget::Remaining() const {
    if (!(limit > 0)) return HUGE_VAL;
    std::lock_guard<std::mutex> lock(mutex);
    return std::max(0.0, limit - committed);
}

void MemoryBudget::Charge(double bytes, const std::string& what) {
    if (!(bytes >= 0)) bytes = HUGE_VAL;  // an estimate that overflowed
    std::lock_guard<std::mutex> lock(mutex);
    if (limit > 0 && committed + bytes > limit) {
        std::string limitText =
            explicitLimit ? "the memory limit of " + FormatBytes(limit) + " (--memory-limit)"
                          : "this machine's " + FormatBytes(limit) + " of memory";
        throw MemoryLimitError(what + " needs " + FormatBytes(bytes) +
                               (committed > 0 ? ", which with the " + FormatBytes(committed) +
                                                    " already committed passes "
                                              : ", more than ") +
                               limitText);
    }
    committed += bytes;
}

void MemoryBudget::Release(double bytes) {
    std::lock_guard<std::mutex> lock(mutex);
    committed = bytes > 0 && bytes < committed ? committed - bytes : (bytes > 0 ? 0 : committed);
}

std::optional<double> MemoryBudget::ParseSize(std::string_view text) {
    std::string s(text);
    char* end = nullptr;
    double value = std::strtod(s.c_str(), &end);
    if (end == s.c_str()) return std::nullopt;
    std::string unit(end);
    while (!unit.empty() && std::isspace(static_cast<unsigned char>(unit.front())))
        unit.erase(unit.begin());
    if (!unit.empty() && (unit.back() == 'B' || unit.back() == 'b')) unit.pop_back();
    double scale = 1;
    bool binary = unit.size() == 2 && (unit[1] == 'i' || unit[1] == 'I');
    if (!unit.empty()) {
        if (unit.size() > 2 || (unit.size() == 2 && !binary)) return std::nullopt;
        double base = binary ? 1024 : 1000;
        switch (std::toupper(static_cast<unsigned char>(unit[0]))) {
            case 'K':
                scale = base;
                break;
            case 'M':
                scale = base * base;
                break;
            case 'G':
                scale = base * base * base;
                break;
            case 'T':
                scale = base * base * base * base;
                break;
            default:
                return std::nullopt;
        }
    }
    double bytes = value * scale;
    if (!(bytes > 0) || !std::isfinite(bytes)) return std::nullopt;
    return bytes;
}

}  // namespace kiln
