#pragma once

#include <QList>
#include <QString>
#include <QStringList>

#include <vector>

class QPainter;
class QFontMetrics;
class QRectF;

// Online values in the ST and IL editors: which variables each line mentions, and the small
// "name = value" boxes drawn after the end of the line while the program runs (the line-end
// display keeps the text where it is, so nothing the user reads moves under the cursor).
namespace iec::editors {

// The variable references of every line (index = 0-based line), each path once, in the order
// they first appear: "Count", "Tank.Level", "Values[2]", "%IX0.1". Calls (`F(...)`), formal
// parameters inside calls (`IN :=`), labels (`L1:`) and keywords are left out; so are array
// elements with a computed index, whose value depends on the moment.
std::vector<QStringList> variablePathsByLine(const QString &text);

// The name the runtime knows a path by: "Main.Count" for a variable of instance Main; direct
// addresses are global ("%IX0.1").
QString onlineName(const QString &instance, const QString &path);

// One box after a line's text.
struct OnlineChip {
    QString label; // the path as written
    QString value; // IEC literal; empty: no value (an unknown name)
    bool forced = false;

    bool operator==(const OnlineChip &) const = default;
};

// Draws `chips` left to right from `x` inside the line's rectangle. Structured values (FB
// instances, arrays) are shortened so that one line never grows into a screenful.
void paintOnlineChips(QPainter &painter, const QRectF &line, qreal x, const QList<OnlineChip> &chips,
                      const QFontMetrics &metrics);

// What a chip shows: "Count = 42"; long values end in "…".
QString chipText(const OnlineChip &chip);

} // namespace iec::editors
