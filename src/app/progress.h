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

#include "render/renderer.h"

namespace kiln {

// The kiln command's view of a render (a RenderObserver): out == nullptr disables output.
// The reporter prints from its own thread, started by Started(); Advanced() is wait-free and
// may be called from any thread.
class ProgressReporter : public RenderObserver {
  public:
    ProgressReporter(std::ostream* out, bool isTerminal);
    ~ProgressReporter() override;
    ProgressReporter(const ProgressReporter&) = delete;
    ProgressReporter& operator=(const ProgressReporter&) = delete;

    // totalWork counts pixel samples.
    void Started(int64_t totalWork, const std::string& title) override;
    void Advanced(int64_t work) override { done.fetch_add(work, std::memory_order_relaxed); }
    // Stops the printing thread and prints the final line.
    void Finished() override;
    double ElapsedSeconds() const;

    // Formats a duration as e.g. "1m23s" or "4.2s".
    static std::string FormatDuration(double seconds);

  private:
    void PrintLoop();
    void Print(bool final);

    int64_t total = 1;
    std::string title;
    std::ostream* out;
    const bool terminal;
    std::atomic<int64_t> done{0};
    std::chrono::steady_clock::time_point start;
    std::chrono::steady_clock::time_point lastPlainLine;
    std::mutex mutex;
    std::condition_variable cv;
    bool exitThread = false, finished = false;
    std::thread thread;
};

}  // namespace kiln
