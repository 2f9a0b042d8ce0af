#include "app/searchresultspane.h"

#include "app/documentarea.h"
#include "app/adddatatexteditor.h"
#include "editors/declarations/declarationeditor.h"
#include "editors/globals/globallisteditor.h"
#include "editors/text/codeeditor.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTextBlock>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace iec::app {

namespace {

enum Column { PlaceColumn, LocationColumn, AccessColumn, TextColumn, ColumnCount };

} // namespace

QString hitLocationText(const SearchHit &hit)
{
    if (hit.isDeclaration())
        return SearchResultsPane::tr("declaration");
    if (hit.localId)
        return SearchResultsPane::tr("element %1").arg(*hit.localId);
    if (hit.line > 0)
        return SearchResultsPane::tr("line %1, column %2").arg(hit.line).arg(hit.column);
    return {};
}

SearchResultsPane::SearchResultsPane(QWidget *parent)
    : QWidget(parent)
    , m_title(new QLabel(this))
    , m_list(new QTreeWidget(this))
{
    m_list->setObjectName(QStringLiteral("searchResults"));
    m_list->setColumnCount(ColumnCount);
    m_list->setRootIsDecorated(false);
    m_list->setUniformRowHeights(true);
    m_list->setAlternatingRowColors(true);
    m_list->header()->setStretchLastSection(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_title);
    layout->addWidget(m_list);
    connect(m_list, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem *item) {
        const int index = item->data(0, Qt::UserRole).toInt();
        if (index >= 0 && index < int(m_hits.size()))
            Q_EMIT hitActivated(m_hits[size_t(index)]);
    });
    retranslate();
}

void SearchResultsPane::retranslate()
{
    m_list->setHeaderLabels({tr("Place"), tr("Where"), tr("Use"), tr("Text")});
}

void SearchResultsPane::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

QString SearchResultsPane::title() const
{
    return m_title->text();
}

void SearchResultsPane::showHits(const QString &title, const std::vector<SearchHit> &hits)
{
    m_hits = hits;
    m_title->setText(title);
    m_list->clear();
    for (int index = 0; index < int(hits.size()); ++index) {
        const SearchHit &hit = hits[size_t(index)];
        auto *item = new QTreeWidgetItem(m_list,
            {hit.place, hitLocationText(hit), ProjectSearch::accessText(hit.access), hit.text.simplified()});
        item->setData(0, Qt::UserRole, index);
        item->setToolTip(TextColumn, hit.text);
    }
    for (int column = 0; column < ColumnCount - 1; ++column)
        m_list->resizeColumnToContents(column);
}

FindInProjectDialog::FindInProjectDialog(const SearchQuery &initial, QWidget *parent)
    : QDialog(parent)
    , m_text(new QLineEdit(initial.text, this))
    , m_case(new QCheckBox(tr("Match &case"), this))
    , m_word(new QCheckBox(tr("&Whole words"), this))
    , m_regex(new QCheckBox(tr("&Regular expression"), this))
{
    setWindowTitle(tr("Find in Project"));
    m_text->setObjectName(QStringLiteral("findInProjectText"));
    m_case->setChecked(initial.caseSensitive);
    m_word->setChecked(initial.wholeWord);
    m_regex->setChecked(initial.regularExpression);
    auto *form = new QFormLayout;
    form->addRow(tr("Find:"), m_text);
    form->addRow(m_case);
    form->addRow(m_word);
    form->addRow(m_regex);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("Find"));
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
    m_text->selectAll();
}

SearchQuery FindInProjectDialog::query() const
{
    return {m_text->text(), m_case->isChecked(), m_word->isChecked(), m_regex->isChecked()};
}

namespace {

void selectMatch(editors::CodeEditor *editor, const SearchHit &hit)
{
    editor->goToLine(hit.line, hit.column);
    QTextCursor cursor = editor->textCursor();
    cursor.movePosition(QTextCursor::Right, QTextCursor::KeepAnchor, hit.length);
    editor->setTextCursor(cursor);
    editor->setFocus();
}

} // namespace

bool showSearchHit(DocumentArea &documents, const SearchHit &hit)
{
    if (hit.list) {
        auto *editor = qobject_cast<editors::GlobalListEditor *>(documents.openGlobalList(*hit.list));
        return editor && editor->showVariable(hit.variable);
    }
    if (!hit.interfaceName.isEmpty() || (hit.body && !hit.member.isEmpty())) {
        auto *text = qobject_cast<AddDataTextEditor *>(hit.interfaceName.isEmpty() ? documents.openMember(hit.body->pou, hit.member)
                                                                                    : documents.openInterface(hit.interfaceName));
        if (!text || hit.line < 1 || hit.line > text->editor()->document()->blockCount())
            return false;
        selectMatch(text->editor(), hit);
        return true;
    }
    if (!hit.body)
        return false;
    QWidget *document = documents.openBody(*hit.body);
    if (!document)
        return false;
    if (hit.isDeclaration()) {
        editors::DeclarationEditor *declarations = documents.declarationEditorFor(*hit.body);
        return declarations && declarations->showVariable(hit.variable);
    }
    if (hit.localId) {
        QList<QWidget *> widgets = document->findChildren<QWidget *>();
        widgets.prepend(document);
        for (QWidget *widget : std::as_const(widgets)) {
            if (widget->metaObject()->indexOfMethod("showElement(quint64)") >= 0)
                return QMetaObject::invokeMethod(widget, "showElement", Q_ARG(quint64, *hit.localId));
        }
        return true; // the body is open; its editor cannot point at the element yet
    }
    editors::CodeEditor *editor = documents.textEditorFor(*hit.body);
    if (!editor || hit.line < 1 || hit.line > editor->document()->blockCount())
        return false;
    selectMatch(editor, hit);
    return true;
}

} // namespace iec::app
