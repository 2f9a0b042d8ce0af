#include "editors/common/inplaceeditor.h"

#include "editors/text/completion.h"
#include "editors/text/inputassistant.h"

#include <QAbstractItemView>
#include <QCompleter>
#include <QKeyEvent>
#include <QStringListModel>

namespace iec::editors {

InPlaceEditor::InPlaceEditor(const QString &text, Completion completion, const CompletionProvider *provider, QWidget *parent)
    : QLineEdit(text, parent)
    , m_completion(completion)
    , m_provider(provider)
{
    setObjectName(QStringLiteral("inPlaceEditor"));
    setToolTip(tr("Enter applies, Esc cancels, F2 opens the input assistant."));
    selectAll();
    if (m_completion != Completion::None) {
        m_model = new QStringListModel(this);
        m_completer = new QCompleter(m_model, this);
        m_completer->setWidget(this);
        m_completer->setCaseSensitivity(Qt::CaseInsensitive);
        m_completer->setCompletionMode(QCompleter::PopupCompletion);
        connect(m_completer, qOverload<const QString &>(&QCompleter::activated), this, &InPlaceEditor::insertCompletion);
        connect(this, &QLineEdit::textEdited, this, &InPlaceEditor::updatePopup);
    }
}

QStringList InPlaceEditor::completions() const
{
    if (m_completion == Completion::None)
        return {};
    const CompletionContext context = completionContext(text(), cursorPosition());
    QStringList names;
    for (const CompletionItem &item : completionItems(context, m_provider, TextLanguage::ST)) {
        const bool block = item.kind == CompletionItem::Kind::FunctionBlock || item.kind == CompletionItem::Kind::Function;
        if (m_completion == Completion::BlockTypes && !block)
            continue;
        // A name field holds a variable or a value: statement keywords (WHILE for "W") and type
        // names would only be taken by Enter by mistake; TRUE and FALSE stay.
        const bool literal = item.text.compare(QLatin1String("TRUE"), Qt::CaseInsensitive) == 0
            || item.text.compare(QLatin1String("FALSE"), Qt::CaseInsensitive) == 0;
        if (m_completion == Completion::Names && !literal
            && (item.kind == CompletionItem::Kind::Keyword || item.kind == CompletionItem::Kind::TypeName))
            continue;
        names << item.text;
    }
    return names;
}

void InPlaceEditor::updatePopup()
{
    const CompletionContext context = completionContext(text(), cursorPosition());
    const QStringList names = completions();
    if (context.prefix.isEmpty() || names.isEmpty()) {
        m_completer->popup()->hide();
        return;
    }
    m_model->setStringList(names);
    m_completer->setCompletionPrefix(context.prefix);
    m_completer->complete();
    // A match is highlighted, so Enter takes it (as in CODESYS): the name typed in full if it is
    // one, else the first. Escape closes the list and keeps the typed text.
    QAbstractItemModel *matches = m_completer->completionModel();
    int row = 0;
    for (int r = 0; r < matches->rowCount(); ++r) {
        if (matches->index(r, 0).data().toString().compare(context.prefix, Qt::CaseInsensitive) == 0) {
            row = r;
            break;
        }
    }
    m_completer->popup()->setCurrentIndex(matches->index(row, 0));
}

void InPlaceEditor::insertCompletion(const QString &completion)
{
    const CompletionContext context = completionContext(text(), cursorPosition());
    QString line = text();
    line.replace(context.prefixStart, cursorPosition() - context.prefixStart, completion);
    const int cursor = context.prefixStart + int(completion.size());
    setText(line);
    setCursorPosition(cursor);
}

void InPlaceEditor::openAssistant()
{
    m_inAssistant = true;
    InputAssistantDialog dialog(TextLanguage::ST, m_provider, this);
    dialog.setCategory(m_completion == Completion::BlockTypes ? InputAssistantDialog::Category::FunctionBlocks
                                                              : InputAssistantDialog::Category::Operands);
    connect(&dialog, &InputAssistantDialog::itemChosen, this, [this](const QString &chosen) {
        if (hasSelectedText())
            del();
        insert(chosen);
    });
    dialog.exec();
    m_inAssistant = false;
    setFocus();
}

void InPlaceEditor::keyPressEvent(QKeyEvent *event)
{
    // While the popup shows, Escape closes it and Tab takes the chosen completion (both the
    // completer's); Enter takes the chosen completion, if any, and applies at once, so typing
    // "TON" and Enter makes the block without a second Enter.
    if (m_completer && m_completer->popup()->isVisible()) {
        switch (event->key()) {
        case Qt::Key_Enter:
        case Qt::Key_Return: {
            const QModelIndex chosen = m_completer->popup()->currentIndex();
            m_completer->popup()->hide();
            if (chosen.isValid())
                insertCompletion(chosen.data().toString());
            finish(true);
            return;
        }
        case Qt::Key_Escape:
        case Qt::Key_Tab:
        case Qt::Key_Backtab:
            event->ignore();
            return;
        default:
            break;
        }
    }
    switch (event->key()) {
    case Qt::Key_Enter:
    case Qt::Key_Return:
        finish(true);
        return;
    case Qt::Key_Escape:
        finish(false);
        return;
    case Qt::Key_F2:
        if (m_completion != Completion::None) {
            openAssistant();
            return;
        }
        break;
    default:
        break;
    }
    QLineEdit::keyPressEvent(event);
}

void InPlaceEditor::focusOutEvent(QFocusEvent *event)
{
    QLineEdit::focusOutEvent(event);
    // The completion popup and the input assistant borrow the focus; anything else commits.
    const bool popup = m_completer && m_completer->popup()->isVisible();
    if (!m_inAssistant && !popup && event->reason() != Qt::PopupFocusReason)
        finish(true);
}

void InPlaceEditor::finish(bool commit)
{
    if (m_done)
        return;
    m_done = true;
    hide();
    if (commit)
        Q_EMIT committed(text().trimmed());
    else
        Q_EMIT cancelled();
    deleteLater();
}

} // namespace iec::editors
