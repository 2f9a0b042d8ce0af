#include "app/messagespane.h"

#include <QApplication>
#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QStyle>
#include <QTreeView>
#include <QVBoxLayout>

#include <algorithm>

namespace iec::app {

QString locationText(const Message &message)
{
    if (message.pouName.isEmpty())
        return {};
    if (message.line > 0 && message.column > 0)
        return MessagesPane::tr("%1, line %2, column %3").arg(message.pouName).arg(message.line).arg(message.column);
    if (message.line > 0)
        return MessagesPane::tr("%1, line %2").arg(message.pouName).arg(message.line);
    if (message.localId && message.column > 0)
        return MessagesPane::tr("%1, element %2, column %3").arg(message.pouName).arg(*message.localId).arg(message.column);
    if (message.localId)
        return MessagesPane::tr("%1, element %2").arg(message.pouName).arg(*message.localId);
    return message.pouName;
}

Message::Severity messageSeverity(model::Diagnostic::Severity severity)
{
    switch (severity) {
    case model::Diagnostic::Severity::Info:
        return Message::Severity::Info;
    case model::Diagnostic::Severity::Warning:
        return Message::Severity::Warning;
    case model::Diagnostic::Severity::Error:
        return Message::Severity::Error;
    }
    return Message::Severity::Error;
}

namespace {

QString severityText(Message::Severity severity)
{
    switch (severity) {
    case Message::Severity::Info:
        return MessagesPane::tr("Info");
    case Message::Severity::Warning:
        return MessagesPane::tr("Warning");
    case Message::Severity::Error:
        return MessagesPane::tr("Error");
    }
    return {};
}

QIcon severityIcon(Message::Severity severity)
{
    const QStyle *style = QApplication::style();
    switch (severity) {
    case Message::Severity::Info:
        return style->standardIcon(QStyle::SP_MessageBoxInformation);
    case Message::Severity::Warning:
        return style->standardIcon(QStyle::SP_MessageBoxWarning);
    case Message::Severity::Error:
        return style->standardIcon(QStyle::SP_MessageBoxCritical);
    }
    return {};
}

} // namespace

MessageListModel::MessageListModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

void MessageListModel::setMessages(const QString &source, const QList<Message> &messages)
{
    beginResetModel();
    m_entries.removeIf([&](const Entry &entry) { return entry.source == source; });
    for (const Message &message : messages)
        m_entries.append({source, message});
    // Errors first, so the one to fix is at the top; stable, so each source keeps its order.
    std::stable_sort(m_entries.begin(), m_entries.end(), [](const Entry &a, const Entry &b) {
        return a.message.severity > b.message.severity;
    });
    endResetModel();
}

void MessageListModel::clear()
{
    beginResetModel();
    m_entries.clear();
    endResetModel();
}

int MessageListModel::count(Message::Severity severity) const
{
    return int(std::count_if(m_entries.begin(), m_entries.end(),
                             [&](const Entry &entry) { return entry.message.severity == severity; }));
}

int MessageListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_entries.size());
}

int MessageListModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant MessageListModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_entries.size())
        return {};
    const Message &message = m_entries.at(index.row()).message;
    switch (index.column()) {
    case SeverityColumn:
        if (role == Qt::DisplayRole)
            return severityText(message.severity);
        if (role == Qt::DecorationRole)
            return severityIcon(message.severity);
        break;
    case TextColumn:
        if (role == Qt::DisplayRole || role == Qt::ToolTipRole)
            return message.text;
        break;
    case LocationColumn:
        if (role == Qt::DisplayRole)
            return locationText(message);
        break;
    default:
        break;
    }
    return {};
}

QVariant MessageListModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case SeverityColumn:
        return MessagesPane::tr("Severity");
    case TextColumn:
        return MessagesPane::tr("Description");
    case LocationColumn:
        return MessagesPane::tr("Location");
    default:
        return {};
    }
}

MessagesPane::MessagesPane(QWidget *parent)
    : QWidget(parent)
    , m_model(new MessageListModel(this))
    , m_view(new QTreeView(this))
    , m_summary(new QLabel(this))
{
    m_view->setObjectName(QStringLiteral("messageList"));
    m_view->setModel(m_model);
    m_view->setRootIsDecorated(false);
    m_view->setUniformRowHeights(true);
    m_view->setAlternatingRowColors(true);
    m_view->header()->setStretchLastSection(false);
    m_view->header()->setSectionResizeMode(MessageListModel::TextColumn, QHeaderView::Stretch);
    m_view->header()->setSectionResizeMode(MessageListModel::SeverityColumn, QHeaderView::ResizeToContents);
    m_view->header()->setSectionResizeMode(MessageListModel::LocationColumn, QHeaderView::ResizeToContents);
    m_summary->setObjectName(QStringLiteral("messageSummary"));

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_view);
    layout->addWidget(m_summary);

    connect(m_view, &QTreeView::activated, this,
            [this](const QModelIndex &index) { Q_EMIT messageActivated(m_model->message(index.row())); });
    connect(m_model, &QAbstractItemModel::modelReset, this, &MessagesPane::updateSummary);
    updateSummary();
}

QString MessagesPane::summary() const
{
    // No plural forms: English would need a translation file of its own for them.
    return tr("Errors: %1, warnings: %2")
        .arg(m_model->count(Message::Severity::Error))
        .arg(m_model->count(Message::Severity::Warning));
}

void MessagesPane::updateSummary()
{
    m_summary->setText(summary());
}

void MessagesPane::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        updateSummary();
    QWidget::changeEvent(event);
}

} // namespace iec::app
