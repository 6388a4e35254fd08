#include "app/progress.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace kiln {

ProgressReporter::ProgressReporter(std::ostream* out, bool isTerminal)
    : out(out), terminal(isTerminal) {}

void ProgressReporter::Started(int64_t totalWork, const std::string& renderTitle) {
    total = std::max<int64_t>(1, totalWork);
    title = renderTitle;
    done = 0;
    start = lastPlainLine = std::chrono::steady_clock::now();
    if (out && !thread.joinable()) thread = std::thread([this] { PrintLoop(); });
}

ProgressReporter::~ProgressReporter() { Finished(); }

double ProgressReporter::ElapsedSeconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string ProgressReporter::FormatDuration(double s) {
    char buf[64];
    if (!std::isfinite(s)) return "--";
    if (s < 60)
        std::snprintf(buf, sizeof(buf), "%.1fs", s);
    else if (s < 3600)
        std::snprintf(buf, sizeof(buf), "%dm%02ds", int(s) / 60, int(s) % 60);
    else
        std::snprintf(buf, sizeof(buf), "%dh%02dm", int(s) / 3600, (int(s) / 60) % 60);
    return buf;
}

void ProgressReporter::PrintLoop() {
    std::unique_lock<std::mutex> lock(mutex);
    // Terminal: redraw twice a second. Otherwise: one line every 10 seconds.
    auto period = terminal ? std::chrono::milliseconds(500) : std::chrono::milliseconds(1000);
    while (!exitThread) {
        cv.wait_for(lock, period);
        if (exitThread) break;
        auto now = std::chrono::steady_clock::now();
        if (!terminal && now - lastPlainLine < std::chrono::seconds(10)) continue;
        lastPlainLine = now;
        Print(false);
    }
}

void ProgressReporter::Print(bool final) {
    int64_t d = std::min(done.load(std::memory_order_relaxed), total);
    double frac = double(d) / double(total);
    double elapsed = ElapsedSeconds();
    double rate = elapsed > 0 ? d / elapsed : 0;
    double eta = (d > 0 && !final) ? elapsed * (1 - frac) / frac : 0;
    std::ostringstream line;
    char pct[16];
    std::snprintf(pct, sizeof(pct), "%5.1f%%", 100 * frac);
    char rateStr[32];
    std::snprintf(rateStr, sizeof(rateStr), "%.3g", rate);
    if (terminal) {
        const int width = 30;
        int filled = int(frac * width);
        line << "\r" << title << " [" << std::string(filled, '=')
             << std::string(width - filled, ' ') << "] " << pct << "  " << rateStr
             << " samples/s  ";
        line << (final ? "done in " + FormatDuration(elapsed) : "ETA " + FormatDuration(eta))
             << "   ";
        if (final) line << "\n";
    } else {
        line << title << ": " << pct << " (" << rateStr << " samples/s, elapsed "
             << FormatDuration(elapsed);
        if (!final) line << ", ETA " << FormatDuration(eta);
        line << ")\n";
    }
    *out << line.str() << std::flush;
}

void ProgressReporter::Finished() {
    {
        std::lock_guard<std::mutex> lock(mutex);
        if (finished) return;
        finished = true;
        exitThread = true;
    }
    cv.notify_all();
    if (!thread.joinable()) return;
    thread.join();
    if (terminal) Print(true);
}

}  // namespace kiln
