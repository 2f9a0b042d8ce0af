#include "app/treeicons.h"

#include <QApplication>
#include <QHash>
#include <QPainter>
#include <QStyle>

namespace iec::app {

using editors::EditorLanguage;

namespace {

QColor languageColour(EditorLanguage language)
{
    switch (language) {
    case EditorLanguage::ST:
        return QColor(0x1e, 0x5a, 0xa8);
    case EditorLanguage::IL:
        return QColor(0x5f, 0x63, 0x68);
    case EditorLanguage::LD:
        return QColor(0x2e, 0x7d, 0x32);
    case EditorLanguage::FBD:
        return QColor(0xc7, 0x62, 0x00);
    case EditorLanguage::CFC:
        return QColor(0x00, 0x79, 0x6b);
    case EditorLanguage::SFC:
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

QString languageName(EditorLanguage language)
{
    switch (language) {
    case EditorLanguage::ST:
        return ProjectTreeModel::tr("Structured Text (ST)");
    case EditorLanguage::IL:
        return ProjectTreeModel::tr("Instruction List (IL)");
    case EditorLanguage::LD:
        return ProjectTreeModel::tr("Ladder Diagram (LD)");
    case EditorLanguage::FBD:
        return ProjectTreeModel::tr("Function Block Diagram (FBD)");
    case EditorLanguage::CFC:
        return ProjectTreeModel::tr("Continuous Function Chart (CFC)");
    case EditorLanguage::SFC:
        return ProjectTreeModel::tr("Sequential Function Chart (SFC)");
    }
    return {};
}

QIcon languageIcon(EditorLanguage language)
{
    // Painted once per language and size; the tree asks for them for every visible row.
    static QHash<int, QIcon> cache;
    const auto it = cache.constFind(int(language));
    if (it != cache.constEnd())
        return *it;
    QIcon icon;
    for (const int size : {16, 24, 32})
        icon.addPixmap(badge(editors::editorLanguageName(language), languageColour(language), size));
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
    case ProjectTreeModel::NodeKind::Interface:
        return style->standardIcon(QStyle::SP_FileDialogInfoView);
    default:
        return {};
    }
}

} // namespace iec::app
