#pragma once

#include <QString>

namespace iec::interp {

// The variable types of Beremiz's SVGHMI extension (`upperName`: upper case) and the elementary
// type each stands for (empty: not one of them). Beremiz's SVGHMI library declares HMI_BOOL as
// BOOL and so on, and binds such variables to the web HMI; here they are plain variables, so the
// logic still runs (and the data type editor accepts them).
[[nodiscard]] QString svgHmiBaseType(const QString &upperName);

} // namespace iec::interp
