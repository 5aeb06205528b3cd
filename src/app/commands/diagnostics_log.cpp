#include "app/commands/diagnostics_log.h"

#include <cstdio>

#include "app/run/scene_source.h"

namespace app {
namespace {

std::string format(const char* pattern, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, pattern, value);
    return buffer;
}

}  // namespace

std::string hexHash(std::uint64_t hash) {
    char buffer[20];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(hash));
    return buffer;
}

DiagnosticsLog::DiagnosticsLog(const std::string& path) : path_(path) {
    if (endsWith(path, ".jsonl")) {
        csv_ = false;
    } else if (!endsWith(path, ".csv")) {
        throw UsageError("--out " + path + ": the file must end in .csv or .jsonl");
    }
    checkWritable("--out", path);  // a folder of that name is said so, not found at the end as a full disk
    // Written beside it and moved over it once whole: a run killed half way (timeout, Ctrl-C)
    // leaves the .part, not a log cut in mid-line that reads as the whole run.
    file_.open(path + ".part");
    if (!file_) throw UsageError("--out " + path + ": cannot open the file for writing");
    file_.precision(17);
    if (csv_) {
        file_ << "step,time_s,kinetic_J,potential_J,total_J,modified_J,px,py,pz,"
                 "sphere_contacts,wall_contacts,max_penetration_r,hash\n";
    }
}

DiagnosticsLog::~DiagnosticsLog() {
    if (finished_) return;
    file_.close();
    std::remove((path_ + ".part").c_str());
}

void DiagnosticsLog::finish() {
    finished_ = true;
    file_.close();
    const std::string part = path_ + ".part";
    if (!file_ || std::rename(part.c_str(), path_.c_str()) != 0) {
        std::remove(part.c_str());  // not a truncated log that reads as the whole run
        throw UsageError("--out " + path_ + ": cannot be written whole (is the disk full?)");
    }
}

void DiagnosticsLog::write(std::uint64_t step, double time, const physics::Diagnostics& d) {
    if (csv_) {
        file_ << step << ',' << time << ',' << d.kinetic << ',' << d.potential << ',' << d.total
              << ',' << d.modified << ',' << d.momentum.x << ',' << d.momentum.y << ','
              << d.momentum.z << ',' << d.sphereContacts << ',' << d.wallContacts << ','
              << d.maxPenetration << ',' << hexHash(d.hash) << '\n';
        failedAt(step);
        return;
    }
    file_ << "{\"step\":" << step << ",\"time_s\":" << time << ",\"kinetic_J\":" << d.kinetic
          << ",\"potential_J\":" << d.potential << ",\"total_J\":" << d.total
          << ",\"modified_J\":" << d.modified << ",\"momentum\":[" << d.momentum.x << ','
          << d.momentum.y << ',' << d.momentum.z << "],\"sphere_contacts\":" << d.sphereContacts
          << ",\"wall_contacts\":" << d.wallContacts << ",\"max_penetration_r\":"
          << d.maxPenetration << ",\"hash\":\"" << hexHash(d.hash) << "\"}\n";
    failedAt(step);
}

void DiagnosticsLog::failedAt(std::uint64_t step) const {
    if (file_) return;
    throw UsageError("--out " + path_ + ": cannot be written whole (is the disk full?); the run stopped at step " +
                     std::to_string(step));
}

std::string summarize(const physics::Diagnostics& d) {
    const glm::dvec3 p = physics::momentumShown(d);  // kg m/s, as the readouts show it (the JSON log: raw)
    return "E_kin " + format("%.6g", d.kinetic) + " J, E_pot " + format("%.6g", d.potential) +
           " J, E " + format("%.6g", d.total) + " J, E~ " + format("%.6g", d.modified) +
           " J | p (" + format("%.3g", p.x) + ", " + format("%.3g", p.y) + ", " +
           format("%.3g", p.z) + ") kg m/s | contacts " +
           std::to_string(d.sphereContacts) + " sphere + " + std::to_string(d.wallContacts) +
           " wall | max penetration " + format("%.2f", 100.0 * d.maxPenetration) + " % r | hash " +
           hexHash(d.hash);
}

}  // namespace app
