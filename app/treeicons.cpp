#include "app/treeicons.h"

#include <QApplication>
#include <QHash>
#include <QPainter>
#include <QStyle>

namespace iec::app {

namespace {

QColor languageColour(model::BodyLanguage language)
{
    switch (language) {
    case model::BodyLanguage::ST:
        return QColor(0x1e, 0x5a, 0xa8);
    case model::BodyLanguage::IL:
        return QColor(0x5f, 0x63, 0x68);
    case model::BodyLanguage::LD:
        return QColor(0x2e, 0x7d, 0x32);
    case model::BodyLanguage::FBD:
        return QColor(0xc7, 0x62, 0x00);
    case model::BodyLanguage::SFC:
        return QColor(0x6a, 0x1b, 0x9a);
    }
    return Qt::gray;
}

QPixmap badge(const QString &text, const QColor &colour, int size)
{
    QPixmap pixmap(size, size);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(Qt::NoPen);
    painter.setBrush(colour);
    painter.drawRoundedRect(QRectF(0.5, 0.5, size - 1, size - 1), size / 5.0, size / 5.0);
    QFont font = QApplication::font();
    font.setBold(true);
    font.setPixelSize(text.size() > 2 ? size * 5 / 16 : size * 7 / 16);
    painter.setFont(font);
    painter.setPen(Qt::white);
    painter.drawText(QRect(0, 0, size, size), Qt::AlignCenter, text);
    return pixmap;
}

} // namespace

QString languageShortName(model::BodyLanguage language)
{
    switch (language) {
    case model::BodyLanguage::ST:
        return QStringLiteral("ST");
    case model::BodyLanguage::IL:
        return QStringLiteral("IL");
    case model::BodyLanguage::LD:
        return QStringLiteral("LD");
    case model::BodyLanguage::FBD:
        return QStringLiteral("FBD");
    case model::BodyLanguage::SFC:
        return QStringLiteral("SFC");
    }
    return {};
}

QString languageName(model::BodyLanguage language)
{
    switch (language) {
    case model::BodyLanguage::ST:
        return ProjectTreeModel::tr("Structured Text (ST)");
    case model::BodyLanguage::IL:
        return ProjectTreeModel::tr("Instruction List (IL)");
    case model::BodyLanguage::LD:
        return ProjectTreeModel::tr("Ladder Diagram (LD)");
    case model::BodyLanguage::FBD:
        return ProjectTreeModel::tr("Function Block Diagram (FBD)");
    case model::BodyLanguage::SFC:
        return ProjectTreeModel::tr("Sequential Function Chart (SFC)");
    }
    return {};
}

QIcon languageIcon(model::BodyLanguage language)
{
    // Painted once per language and size; the tree asks for them for every visible row.
    static QHash<int, QIcon> cache;
    const auto it = cache.constFind(int(language));
    if (it != cache.constEnd())
        return *it;
    QIcon icon;
    for (const int size : {16, 24, 32})
        icon.addPixmap(badge(languageShortName(language), languageColour(language), size));
    cache.insert(int(language), icon);
    return icon;
}

QIcon nodeIcon(ProjectTreeModel::NodeKind kind)
{
    const QStyle *style = QApplication::style();
    switch (kind) {
    case ProjectTreeModel::NodeKind::Folder:
        return style->standardIcon(QStyle::SP_DirIcon);
    case ProjectTreeModel::NodeKind::DataType:
        return style->standardIcon(QStyle::SP_FileDialogDetailedView);
    case ProjectTreeModel::NodeKind::GlobalVarList:
        return style->standardIcon(QStyle::SP_FileDialogListView);
    case ProjectTreeModel::NodeKind::Configuration:
        return style->standardIcon(QStyle::SP_ComputerIcon);
    case ProjectTreeModel::NodeKind::Resource:
        return style->standardIcon(QStyle::SP_DriveHDIcon);
    case ProjectTreeModel::NodeKind::Task:
        return style->standardIcon(QStyle::SP_BrowserReload);
    default:
        return {};
    }
}

} // namespace iec::app
