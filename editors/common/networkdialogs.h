#pragma once

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <optional>

class QWidget;

namespace iec::editors {

// The questions the network languages (LD, FBD) ask before a command: a network's label, its
// comment, and the label a jump goes to. Empty optional: the user cancelled.
class NetworkDialogs
{
    Q_DECLARE_TR_FUNCTIONS(iec::editors::NetworkDialogs)

public:
    // `network` counts from 0; the dialog says "network 1" for it.
    static std::optional<QString> askLabel(QWidget *parent, int network, const QString &current);
    static std::optional<QString> askComment(QWidget *parent, int network, const QString &current);
    // A label among the networks' `labels`, or a new one typed; empty optional also when blank.
    static std::optional<QString> askJumpTarget(QWidget *parent, const QStringList &labels);
};

} // namespace iec::editors
