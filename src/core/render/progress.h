// Progress reporting for long renders: a live bar with percentage, samples/s and ETA on a
// terminal, plain periodic lines otherwise (logs, CI), and nothing in quiet mode.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>

namespace kiln {

class ProgressReporter {
  public:
    // totalWork counts pixel samples; out == nullptr disables output. The reporter prints
    // from its own thread; Update() is wait-free and may be called from any thread.
    ProgressReporter(int64_t totalWork, std::string title, std::ostream* out, bool isTerminal);
    ~ProgressReporter();
    ProgressReporter(const ProgressReporter&) = delete;
    ProgressReporter& operator=(const ProgressReporter&) = delete;

    void Update(int64_t work) { done.fetch_add(work, std::memory_order_relaxed); }
    // Stops the printing thread and prints the final line.
    void Done();
    double ElapsedSeconds() const;
    int64_t WorkDone() const { return done.load(std::memory_order_relaxed); }

    // Formats a duration as e.g. "1m23s" or "4.2s".
    static std::string FormatDuration(double seconds);

  private:
    void PrintLoop();
    void Print(bool final);

    const int64_t total;
    const std::string title;
    std::ostream* out;
    const bool terminal;
    std::atomic<int64_t> done{0};
    const std::chrono::steady_clock::time_point start;
    std::chrono::steady_clock::time_point lastPlainLine;
    std::mutex mutex;
    std::condition_variable cv;
    bool exitThread = false, finished = false;
    std::thread thread;
};

}  // namespace kiln
