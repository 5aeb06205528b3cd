#pragma once
// Writes a row of diagnostics per sample, as CSV or as JSON lines (by file extension).
#include <fstream>
#include <string>

#include "physics/diagnostics.h"

namespace app {

class DiagnosticsLog {
public:
    // Throws UsageError when the extension is neither .csv nor .jsonl, or the file
    // cannot be opened for writing.
    explicit DiagnosticsLog(const std::string& path);
    // Unfinished (an error ended the run): its .part is removed. A killed run leaves it.
    ~DiagnosticsLog();
    DiagnosticsLog(const DiagnosticsLog&) = delete;
    DiagnosticsLog& operator=(const DiagnosticsLog&) = delete;
    // Throws UsageError once a write has failed (the buffer could not be flushed: a full
    // disk), so that the run stops there rather than stepping on to its end for nothing.
    void write(std::uint64_t step, double time, const physics::Diagnostics& d);
    // Closes the file; throws UsageError when it could not be written whole (a full disk).
    void finish();

private:
    void failedAt(std::uint64_t step) const;  // throws if the file has failed

    std::string path_;
    std::ofstream file_;
    bool csv_ = true;
    bool finished_ = false;
};

// One line for a terminal: energies (J), momentum (kg m/s), contacts, penetration, hash.
std::string summarize(const physics::Diagnostics& d);

std::string hexHash(std::uint64_t hash);

}  // namespace app
