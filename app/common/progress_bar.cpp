#include "common/progress_bar.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

#include <fmt/format.h>

namespace grainlab {

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()),
      terminal_(isatty(STDERR_FILENO) != 0) {}

void ProgressBar::update(double fraction, const std::string& status) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    // A resumed run starts part-way: the rate is the progress made since this bar started.
    if (startFraction_ < 0.0) {
        startFraction_ = fraction;
    }
    const double done = fraction - startFraction_;
    const double eta =
        fraction >= 1.0 ? 0.0 : (done > 1e-6 ? elapsed * (1.0 - fraction) / done : -1.0);
    const auto clock = [](double s) {
        if (s < 0.0) {
            return std::string("-:--:--");
        }
        const long t = static_cast<long>(s + 0.5);
        return fmt::format("{}:{:02}:{:02}", t / 3600, (t / 60) % 60, t % 60);
    };
    if (terminal_) {
        if (now - lastDraw_ < std::chrono::milliseconds(100) && fraction < 1.0) {
            return;
        }
        lastDraw_ = now;
        const int width = 30, filled = static_cast<int>(fraction * width);
        fmt::print(stderr, "\r\033[K{} [{}{}] {:5.1f} % {} ETA {}", label_,
                   std::string(filled, '#'), std::string(width - filled, '-'), 100.0 * fraction,
                   status, clock(eta));
    } else {
        const int decile = static_cast<int>(fraction * 10);
        if (decile == lastDecile_) {
            return;
        }
        lastDecile_ = decile;
        fmt::print(stderr, "{} {:5.1f} % {} elapsed {} ETA {}\n", label_, 100.0 * fraction, status,
                   clock(elapsed), clock(eta));
    }
    std::fflush(stderr);
}

void ProgressBar::note(const std::string& line) {
    if (terminal_) {
        fmt::print(stderr, "\r\033[K");
        lastDraw_ = {}; // redraw the bar at the next update
    }
    fmt::print(stderr, "{}\n", line);
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (terminal_) {
        fmt::print(stderr, "\n");
    }
}

} // namespace grainlab
