#include "editors/text/findreplacebar.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTextBlock>
#include <QTextCursor>
#include <QToolButton>

namespace iec::editors {

int replaceAllInDocument(
    QTextDocument *document, const QString &text, const QString &replacement, QTextDocument::FindFlags flags)
{
    if (!document || text.isEmpty())
        return 0;
    flags &= ~QTextDocument::FindBackward;
    int count = 0;
    QTextCursor edit(document);
    QTextCursor found = document->find(text, 0, flags);
    while (!found.isNull()) {
        if (count == 0)
            edit.beginEditBlock(); // the edit block is the document's: every insert below is one undo step
        found.insertText(replacement);
        ++count;
        found = document->find(text, found.position(), flags);
    }
    if (count > 0)
        edit.endEditBlock();
    return count;
}

FindReplaceBar::FindReplaceBar(QPlainTextEdit *editor, QWidget *parent)
    : QWidget(parent)
    , m_editor(editor)
{
    setObjectName(QStringLiteral("findReplaceBar"));
    m_find = new QLineEdit(this);
    m_find->setPlaceholderText(tr("Find"));
    m_find->setClearButtonEnabled(true);
    m_replace = new QLineEdit(this);
    m_replace->setPlaceholderText(tr("Replace with"));
    m_case = new QCheckBox(tr("Match case"), this);
    m_words = new QCheckBox(tr("Whole words"), this);
    m_status = new QLabel(this);

    auto *previous = new QPushButton(tr("Previous"), this);
    auto *next = new QPushButton(tr("Next"), this);
    auto *replaceOne = new QPushButton(tr("Replace"), this);
    auto *replaceEvery = new QPushButton(tr("Replace All"), this);
    auto *close = new QToolButton(this);
    close->setText(QStringLiteral("✕"));
    close->setToolTip(tr("Close"));
    close->setAutoRaise(true);
    for (QPushButton *button : {previous, next, replaceOne, replaceEvery})
        button->setAutoDefault(false);

    auto *findRow = new QHBoxLayout;
    findRow->addWidget(new QLabel(tr("Find:"), this));
    findRow->addWidget(m_find, 1);
    findRow->addWidget(previous);
    findRow->addWidget(next);
    findRow->addWidget(m_case);
    findRow->addWidget(m_words);
    findRow->addWidget(m_status);
    findRow->addWidget(close);

    m_replaceRow = new QWidget(this);
    auto *replaceRow = new QHBoxLayout(m_replaceRow);
    replaceRow->setContentsMargins(0, 0, 0, 0);
    replaceRow->addWidget(new QLabel(tr("Replace:"), m_replaceRow));
    replaceRow->addWidget(m_replace, 1);
    replaceRow->addWidget(replaceOne);
    replaceRow->addWidget(replaceEvery);
    replaceRow->addStretch();

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->setSpacing(2);
    layout->addLayout(findRow);
    layout->addWidget(m_replaceRow);

    connect(next, &QPushButton::clicked, this, &FindReplaceBar::findNext);
    connect(previous, &QPushButton::clicked, this, &FindReplaceBar::findPrevious);
    connect(replaceOne, &QPushButton::clicked, this, &FindReplaceBar::replace);
    connect(replaceEvery, &QPushButton::clicked, this, &FindReplaceBar::replaceAll);
    connect(m_find, &QLineEdit::returnPressed, this, &FindReplaceBar::findNext);
    connect(m_replace, &QLineEdit::returnPressed, this, &FindReplaceBar::replace);
    connect(m_find, &QLineEdit::textChanged, this, [this] { setStatus({}, false); });
    connect(close, &QToolButton::clicked, this, [this] {
        hide();
        m_editor->setFocus();
        Q_EMIT closed();
    });
}

void FindReplaceBar::activate(bool withReplace)
{
    const QString selected = m_editor->textCursor().selectedText();
    if (!selected.isEmpty() && !selected.contains(QChar::ParagraphSeparator))
        m_find->setText(selected);
    m_replaceRow->setVisible(withReplace);
    show();
    m_find->setFocus();
    m_find->selectAll();
}

void FindReplaceBar::setFindText(const QString &text)
{
    m_find->setText(text);
}

QString FindReplaceBar::findText() const
{
    return m_find->text();
}

void FindReplaceBar::setReplaceText(const QString &text)
{
    m_replace->setText(text);
}

void FindReplaceBar::setCaseSensitive(bool on)
{
    m_case->setChecked(on);
}

void FindReplaceBar::setWholeWords(bool on)
{
    m_words->setChecked(on);
}

QString FindReplaceBar::statusText() const
{
    return m_status->text();
}

bool FindReplaceBar::isReplaceShown() const
{
    return m_replaceRow->isVisibleTo(this);
}

QTextDocument::FindFlags FindReplaceBar::flags() const
{
    QTextDocument::FindFlags result;
    if (m_case->isChecked())
        result |= QTextDocument::FindCaseSensitively;
    if (m_words->isChecked())
        result |= QTextDocument::FindWholeWords;
    return result;
}

void FindReplaceBar::setStatus(const QString &text, bool problem)
{
    m_status->setText(text);
    m_status->setStyleSheet(problem ? QStringLiteral("color: #c00000;") : QString());
}

bool FindReplaceBar::find(bool backward)
{
    const QString text = m_find->text();
    if (text.isEmpty())
        return false;
    QTextDocument::FindFlags options = flags();
    if (backward)
        options |= QTextDocument::FindBackward;
    QTextDocument *document = m_editor->document();
    const QTextCursor current = m_editor->textCursor();
    // Forward searches start after the current match, backward ones before it.
    QTextCursor found = document->find(text, backward ? current.selectionStart() : current.selectionEnd(), options);
    bool wrapped = false;
    if (found.isNull()) {
        QTextCursor from(document);
        if (backward)
            from.movePosition(QTextCursor::End);
        found = document->find(text, from, options);
        wrapped = true;
    }
    if (found.isNull()) {
        setStatus(tr("Not found"), true);
        return false;
    }
    m_editor->setTextCursor(found);
    m_editor->ensureCursorVisible();
    setStatus(wrapped ? tr("Search wrapped") : QString(), false);
    return true;
}

bool FindReplaceBar::findNext()
{
    return find(false);
}

bool FindReplaceBar::findPrevious()
{
    return find(true);
}

bool FindReplaceBar::selectionMatches() const
{
    const QString selected = m_editor->textCursor().selectedText();
    if (selected.isEmpty())
        return false;
    // Let the document decide (it knows whole words): search from the selection start.
    QTextCursor probe = m_editor->document()->find(m_find->text(), m_editor->textCursor().selectionStart(), flags());
    return !probe.isNull() && probe.selectionStart() == m_editor->textCursor().selectionStart()
        && probe.selectionEnd() == m_editor->textCursor().selectionEnd();
}

bool FindReplaceBar::replace()
{
    if (selectionMatches()) {
        QTextCursor cursor = m_editor->textCursor();
        cursor.insertText(m_replace->text());
        m_editor->setTextCursor(cursor);
    }
    return findNext();
}

int FindReplaceBar::replaceAll()
{
    const int count = replaceAllInDocument(m_editor->document(), m_find->text(), m_replace->text(), flags());
    if (count == 0)
        setStatus(tr("Not found"), true);
    else
        setStatus(tr("%n replaced", nullptr, count), false);
    return count;
}

void FindReplaceBar::keyPressEvent(QKeyEvent *event)
{
    if (event->key() == Qt::Key_Escape) {
        hide();
        m_editor->setFocus();
        Q_EMIT closed();
        return;
    }
    QWidget::keyPressEvent(event);
}

} // namespace iec::editors
