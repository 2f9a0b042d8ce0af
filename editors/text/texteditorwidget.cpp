#include "editors/text/texteditorwidget.h"

#include "editors/text/codeeditor.h"
#include "editors/text/findreplacebar.h"

#include <QAction>
#include <QEvent>
#include <QLabel>
#include <QTextDocument>
#include <QVBoxLayout>

namespace iec::editors {

TextEditorWidget::TextEditorWidget(TextLanguage language, QWidget *parent)
    : QWidget(parent)
    , m_editor(new CodeEditor(language, this))
    , m_findBar(new FindReplaceBar(m_editor, this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_onlineBanner = new QLabel(this);
    m_onlineBanner->setObjectName(QStringLiteral("onlineBanner"));
    m_onlineBanner->setContentsMargins(6, 3, 6, 3);
    m_onlineBanner->setWordWrap(true);
    m_onlineBanner->hide();
    layout->addWidget(m_onlineBanner);
    connect(m_editor, &CodeEditor::breakpointToggleRequested, this, [this](int line) { requestBreakpointToggle({line, -1}); });
    connect(m_editor, &CodeEditor::editRefused, this, [this](const QString &message) {
        m_refusalShown.start();
        showBanner(message, true);
    });
    connect(m_editor, &CodeEditor::addToWatchRequested, this,
        [this](const QString &path) { Q_EMIT addToWatchRequested(onlineName(onlineInstance(), path)); });
    layout->addWidget(m_editor, 1);
    layout->addWidget(m_findBar);
    m_findBar->hide();
    setFocusProxy(m_editor);

    // The names let the window's Edit menu find them (app/editactions.h).
    auto addShortcut = [this](const QKeySequence &keys, auto slot, const char *name = "") {
        auto *action = new QAction(this);
        action->setObjectName(QString::fromLatin1(name));
        action->setShortcut(keys);
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        connect(action, &QAction::triggered, this, slot);
        addAction(action);
    };
    addShortcut(QKeySequence::Find, [this] { m_findBar->activate(false); }, "editFind");
    addShortcut(QKeySequence::Replace, [this] {
        if (m_online)
            Q_EMIT m_editor->editRefused(CodeEditor::onlineEditRefusal());
        else
            m_findBar->activate(true);
    }, "editReplace");
    addShortcut(QKeySequence::FindNext, [this] { m_findBar->findNext(); });
    addShortcut(QKeySequence::FindPrevious, [this] { m_findBar->findPrevious(); });
    if (language == TextLanguage::IL)
        createInsertActions();
    retranslate();
}

void TextEditorWidget::createInsertActions()
{
    using Category = InputAssistantDialog::Category;
    const std::pair<const char *, Category> entries[] {{"ilInsertOperator", Category::Operators},
        {"ilInsertOperand", Category::Operands}, {"ilInsertFunction", Category::Functions},
        {"ilInsertFunctionBlock", Category::FunctionBlocks}};
    for (const auto &[name, category] : entries) {
        auto *action = new QAction(this);
        action->setObjectName(QString::fromLatin1(name));
        connect(action, &QAction::triggered, this, [this, category = category] { m_editor->openInputAssistantOn(category); });
        m_insertActions << action;
    }
}

void TextEditorWidget::retranslate()
{
    // The letters are RunPro's: O, P, F, B.
    const char *const texts[] {QT_TR_NOOP("&Operator..."), QT_TR_NOOP("O&perand..."), QT_TR_NOOP("&Function..."),
        QT_TR_NOOP("Function &Block...")};
    for (int index = 0; index < m_insertActions.size(); ++index)
        m_insertActions[index]->setText(tr(texts[index]));
}

void TextEditorWidget::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

// ---- online mode ----------------------------------------------------------------------------

QString TextEditorWidget::onlineInstance() const
{
    return m_instanceProvider ? m_instanceProvider() : QString();
}

const std::vector<QStringList> &TextEditorWidget::linePaths() const
{
    const int revision = m_editor->document()->revision();
    if (revision != m_linePathsRevision) {
        m_linePaths = variablePathsByLine(m_editor->toPlainText());
        m_linePathsRevision = revision;
    }
    return m_linePaths;
}

QStringList TextEditorWidget::onlineNames() const
{
    const QString instance = onlineInstance();
    if (instance.isEmpty())
        return {};
    QStringList names;
    for (const QStringList &paths : linePaths()) {
        for (const QString &path : paths) {
            // A global is named without the instance; the runtime answers whichever exists.
            for (const QString &name : {onlineName(instance, path), path}) {
                if (!names.contains(name, Qt::CaseInsensitive))
                    names.append(name);
            }
        }
    }
    return names;
}

void TextEditorWidget::showBanner(const QString &text, bool warning)
{
    m_onlineBanner->setText(text);
    m_onlineBanner->setStyleSheet(warning ? QStringLiteral("background: #fde2c4; color: #6b3000;")
                                          : QStringLiteral("background: #d7e6fb; color: #12335c;"));
    m_onlineBanner->show();
}

std::optional<OnlineView::Place> TextEditorWidget::breakpointPlace() const
{
    return Place{m_editor->textCursor().blockNumber() + 1, -1};
}

void TextEditorWidget::setBreakpointMarks(const std::vector<Place> &breakpoints, std::optional<Place> halted)
{
    QList<int> lines;
    QList<int> disabled;
    for (const Place &place : breakpoints) {
        if (place.line <= 0)
            continue;
        lines.append(place.line);
        if (!place.enabled)
            disabled.append(place.line);
    }
    m_editor->setBreakpointLines(lines, disabled);
    m_editor->setHaltedLine(halted ? halted->line : 0);
}

void TextEditorWidget::setOnlineSnapshot(const interp::RuntimeSnapshot *snapshot)
{
    if (!snapshot) {
        m_online = false;
        m_editor->setOnline(false);
        m_onlineBanner->hide();
        m_refusalShown.invalidate();
        return;
    }
    if (!m_online) {
        m_online = true;
        m_findBar->hide();
        m_editor->setOnline(true);
    }
    const QString instance = onlineInstance();
    if (!m_refusalShown.isValid() || m_refusalShown.elapsed() > 4000)
        showBanner(tr("Online: %1, cycle %2").arg(instance.isEmpty() ? tr("no instance") : instance).arg(snapshot->cycle),
                   false);
    const std::vector<QStringList> &paths = linePaths();
    std::vector<QList<OnlineChip>> chips(paths.size());
    for (size_t line = 0; line < paths.size(); ++line) {
        for (const QString &path : paths[line]) {
            // The instance's own variable first: it hides a global of the same name.
            const QString local = onlineName(instance, path);
            const QString name = snapshot->values.contains(local) ? local : path;
            const auto value = snapshot->values.constFind(name);
            if (instance.isEmpty() || value == snapshot->values.constEnd())
                continue;
            chips[line].append({path, *value, snapshot->isForced(name)});
        }
    }
    m_editor->setOnlineChips(std::move(chips));
}

} // namespace iec::editors
