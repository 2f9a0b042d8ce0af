#include "model/savefile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

#include <cerrno>

namespace iec::model {

namespace {

// Why opening the temporary file failed, for someone who can do something about it.
QString openFailure(const QFileInfo &target, int code, const QSaveFile &file)
{
    const QString folder = QDir::toNativeSeparators(target.absolutePath());
    if (!QFileInfo::exists(target.absolutePath()))
        return QCoreApplication::translate("iec::model::SaveFile", "the folder %1 does not exist").arg(folder);
    if (target.isDir())
        return QCoreApplication::translate("iec::model::SaveFile", "a folder of that name is in the way");
    if (code == EACCES || code == EPERM || code == EROFS || !QFileInfo(target.absolutePath()).isWritable())
        return QCoreApplication::translate("iec::model::SaveFile", "the folder %1 is read-only, or you may not write in it").arg(folder);
    if (target.exists() && !target.isWritable())
        return QCoreApplication::translate("iec::model::SaveFile", "the file is read-only");
    return file.errorString();
}

// Why writing failed: errno from the failed write, or Qt's description.
QString writeFailure(int code, const QSaveFile &file)
{
    if (code == ENOSPC || code == EDQUOT)
        return QCoreApplication::translate("iec::model::SaveFile", "the disk is full");
    if (code == EFBIG)
        return QCoreApplication::translate("iec::model::SaveFile", "the file would be larger than the system allows");
    return file.errorString();
}

} // namespace

bool saveFileAtomically(const QString &path, const QByteArray &bytes, QString *error)
{
    const QFileInfo target(path);
    const auto fail = [&](const QString &reason) {
        if (error)
            *error = QCoreApplication::translate("iec::model::SaveFile", "%1 was not saved: %2. The file on the disk is unchanged.")
                         .arg(QDir::toNativeSeparators(target.absoluteFilePath()), reason);
        return false;
    };
    QSaveFile file(path);
    errno = 0;
    // Unbuffered: QSaveFile::commit() ignores a failed flush of buffered data and would put a
    // cut-off file in place of the old one (a full disk, a file size limit). Written straight
    // through, every short write is seen here, and the size is checked once more before the rename.
    if (target.isDir() || !file.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return fail(openFailure(target, errno, file));
    errno = 0;
    const bool written = file.write(bytes) == bytes.size() && file.size() == bytes.size();
    const int writeCode = errno;
    if (!written) {
        file.cancelWriting();
        return fail(writeFailure(writeCode, file));
    }
    errno = 0;
    if (!file.commit()) // flushes, syncs and renames; a full disk usually shows here
        return fail(writeFailure(errno != 0 ? errno : writeCode, file));
    return true;
}

} // namespace iec::model
