#pragma once

#include <QStringList>

class QSettings;

namespace iec::app {

// File → Recent Projects: the last projects opened or saved, newest first, at most kMaxCount,
// kept in QSettings under "recentFiles" so every window and the next start see them.
class RecentFiles
{
public:
    static constexpr int kMaxCount = 8;

    [[nodiscard]] static QStringList load(const QSettings &store);
    // Puts `path` (made absolute) first, dropping an older entry for it and the oldest beyond the cap.
    static void add(QSettings &store, const QString &path);
    static void remove(QSettings &store, const QString &path);
};

} // namespace iec::app
