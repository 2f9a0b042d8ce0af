#include "interpreter/graphical/graphicallowering.h"

namespace iec::interp::graphical {

// Placeholder until the LD/FBD lowering lands: says what cannot run.
std::vector<ast::Stmt> lowerBody(const model::Body &body, LoweringContext &context)
{
    context.diagnostics.error(context.owner, {},
        QStringLiteral("%1 is written in %2, which this version cannot run yet.")
            .arg(context.owner, body.language() == model::BodyLanguage::LD ? QStringLiteral("LD") : QStringLiteral("FBD")),
        QStringLiteral("write it in ST or IL to run it now"));
    return {};
}

std::optional<ast::Expr> lowerInput(const model::Body &body, const model::ConnectionPointIn &input,
    LoweringContext &context)
{
    Q_UNUSED(body);
    Q_UNUSED(input);
    context.diagnostics.error(context.owner, {},
        QStringLiteral("Graphical conditions cannot run yet."));
    return std::nullopt;
}

} // namespace iec::interp::graphical
