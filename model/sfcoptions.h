#pragma once

#include "model/elements_sfc.h"

#include <QString>

// Step properties that TC6 has no element for (CoDeSys keeps them in its own addData): entry,
// exit and active actions, minimum and maximum time, and whether the step is an IEC step or a
// simplified step. They live in one addData entry of the step, named kStepOptionsAddDataName,
// so other tools keep them untouched and the file stays valid TC6.
namespace iec::model {

inline constexpr const char *kStepOptionsAddDataName = "https://iec-studio.org/sfc/step";

struct StepOptions {
    bool simplified = false; // CoDeSys "simplified step": no IEC action blocks, an active action
    QString entryAction;     // POU action run once when the step becomes active ("E" corner)
    QString exitAction;      // POU action run once when the step is left ("X" corner)
    QString activeAction;    // POU action run every cycle while the step is active (triangle)
    QString minTime;         // IEC TIME literal or TIME variable name; empty: no limit
    QString maxTime;

    [[nodiscard]] bool isDefault() const { return *this == StepOptions {}; }
    bool operator==(const StepOptions &) const = default;
};

// The options stored in the step's addData; defaults when there is no entry or it is malformed.
StepOptions stepOptions(const Step &step);
// Replaces (or, for default options, removes) the entry; other addData entries stay as they are.
void setStepOptions(Step &step, const StepOptions &options);

} // namespace iec::model
