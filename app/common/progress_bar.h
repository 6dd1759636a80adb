#pragma once
// A one-line terminal progress bar with an ETA, redrawn in place on stderr (only when stderr is
// a terminal; otherwise a line every 10 %). Main thread only.

#include <chrono>
#include <string>

namespace grainlab {

class ProgressBar {
public:
    explicit ProgressBar(std::string label);
    /// fraction in [0, 1]; `status` is shown after the bar.
    void update(double fraction, const std::string& status = {});
    /// Prints `line` on a line of its own above the bar (the bar is redrawn at the next update).
    void note(const std::string& line);
    void finish();

private:
    std::string label_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point lastDraw_{};
    bool terminal_ = false;
    int lastDecile_ = -1;
    double startFraction_ = -1.0; ///< fraction at the first update (a resumed run starts late)
};

} // namespace grainlab
