#pragma once

#include "model/project.h"

#include <QString>
#include <QStringList>

#include <optional>

// The Trace pane's configuration as the project file keeps it: in our own addData of the
// project (other tools ignore it). The model only stores it; the recording is the runtime's
// (interpreter/runtime/tracerecorder.h), the lanes the pane's.
namespace iec::model {

inline constexpr const char *kTraceAddDataName = "https://iec-studio.org/trace";

struct SavedTrace {
    QStringList variables;   // in lane order
    QStringList hidden;      // lanes switched off
    int everyCycles = 1;
    int capacity = 10'000;
    int trigger = 0;         // 0 none, 1 rising edge, 2 falling edge, 3 level
    QString triggerVariable;
    double triggerLevel = 0.5;
    int samplesAfterTrigger = 100;
    QString recordCondition;
    int historyScans = 1000; // scans kept to go back to

    bool operator==(const SavedTrace &) const = default;
};

// The configuration saved in `project`; nullopt when there is none or it does not read.
std::optional<SavedTrace> savedTrace(const Project &project);
// Replaces the entry; the default configuration removes it, so the file stays as before.
void setSavedTrace(Project &project, const SavedTrace &trace);

} // namespace iec::model
