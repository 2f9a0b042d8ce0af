#include "interpreter/sfc/sfclowering.h"

namespace iec::interp::sfc {

// Placeholder until the SFC engine lands.
void lowerChart(const model::Pou &pou, ast::Pou &result, Diagnostics &diagnostics)
{
    Q_UNUSED(result);
    diagnostics.error(pou.name, {},
        QStringLiteral("%1 is written in SFC, which this version cannot run yet.").arg(pou.name),
        QStringLiteral("write it in ST or IL to run it now"));
}

} // namespace iec::interp::sfc
