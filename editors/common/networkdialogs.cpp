#include "editors/common/networkdialogs.h"

#include <QInputDialog>

namespace iec::editors {

std::optional<QString> NetworkDialogs::askLabel(QWidget *parent, int network, const QString &current)
{
    bool ok = false;
    const QString label = QInputDialog::getText(parent, tr("Network Label"), tr("Label of network %1 (empty: none):").arg(network + 1),
        QLineEdit::Normal, current, &ok);
    return ok ? std::optional<QString>(label) : std::nullopt;
}

std::optional<QString> NetworkDialogs::askComment(QWidget *parent, int network, const QString &current)
{
    bool ok = false;
    const QString comment = QInputDialog::getMultiLineText(parent, tr("Network Comment"), tr("Comment of network %1:").arg(network + 1), current, &ok);
    return ok ? std::optional<QString>(comment) : std::nullopt;
}

std::optional<QString> NetworkDialogs::askJumpTarget(QWidget *parent, const QStringList &labels)
{
    bool ok = false;
    const QString label = QInputDialog::getItem(parent, tr("Jump"), tr("Jump to the network with the label:"), labels, 0, true, &ok);
    return ok && !label.trimmed().isEmpty() ? std::optional<QString>(label) : std::nullopt;
}

} // namespace iec::editors
