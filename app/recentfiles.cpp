#include "app/recentfiles.h"

#include <QFileInfo>
#include <QSettings>

namespace iec::app {

namespace {

const QString kRecentFiles = QStringLiteral("recentFiles");

} // namespace

QStringList RecentFiles::load(const QSettings &store)
{
    QStringList files = store.value(kRecentFiles).toStringList();
    // The settings file may have been edited by hand; keep the promise of the cap anyway.
    files.removeAll(QString());
    return files.mid(0, kMaxCount);
}

void RecentFiles::add(QSettings &store, const QString &path)
{
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QStringList files = load(store);
    files.removeAll(absolute);
    files.prepend(absolute);
    store.setValue(kRecentFiles, files.mid(0, kMaxCount));
}

void RecentFiles::remove(QSettings &store, const QString &path)
{
    QStringList files = load(store);
    files.removeAll(QFileInfo(path).absoluteFilePath());
    store.setValue(kRecentFiles, files);
}

} // namespace iec::app
