// Progress: how far a long core job has come and whether its caller wants it to stop (any thread).
#pragma once

#include <algorithm>
#include <atomic>
#include <functional>
#include <mutex>
#include <string>

namespace pf {

// The one progress and cancellation channel of long core jobs (the mosaic, ...). The job calls
// report() from whichever thread does the work and checks cancelled() between steps; the CLI prints
// the reports, the GUI forwards them to a progress bar (queued to its own thread) and calls
// cancel() from its Cancel button. Reports never go backwards and are serialised, so a callback
// needs no lock.
class Progress {
public:
    using Callback = std::function<void(double fraction, const std::string& stage)>;

    Progress() = default;
    explicit Progress(Callback callback) : m_callback(std::move(callback)) {}
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    // Asks the job to stop at its next check; it then returns ErrorCode::Cancelled.
    void cancel() { m_cancelled.store(true); }
    bool cancelled() const { return m_cancelled.load(); }

    // `fraction` of the whole job in [0, 1] and the stage in words ("warping photos").
    void report(double fraction, const std::string& stage) {
        std::lock_guard<std::mutex> lock(m_mutex);
        fraction = std::clamp(fraction, m_last, 1.0);
        m_last = fraction;
        if (m_callback)
            m_callback(fraction, stage);
    }
    double last() const {
        std::lock_guard<std::mutex> lock(m_mutex);
        return m_last;
    }

private:
    Callback m_callback;
    std::atomic<bool> m_cancelled{false};
    mutable std::mutex m_mutex;
    double m_last = 0.0;
};

} // namespace pf
