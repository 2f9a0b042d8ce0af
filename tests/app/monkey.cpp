#include "monkey.h"

#include "app/documentarea.h"
#include "app/mainwindow.h"
#include "model/projectmodel.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QFileDialog>
#include <QGraphicsItem>
#include <QGraphicsScene>
#include <QGraphicsView>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QTest>
#include <QTextCursor>
#include <QTimer>
#include <QUndoGroup>
#include <QUndoStack>
#include <QWheelEvent>

#include <algorithm>

namespace monkey {

namespace {

// Actions a monkey must not take: they leave the window, open files or print.
bool forbidden(const QAction *action)
{
    static const QRegularExpression words(QStringLiteral("print|export|import|open|close|quit|exit|new|save|about|settings|preferences|recent|example"),
                                          QRegularExpression::CaseInsensitiveOption);
    return action->isSeparator() || action->menu() || words.match(action->objectName()).hasMatch()
        || words.match(action->text()).hasMatch();
}

// Pieces of IEC text, valid and not: what a student types.
const QStringList &snippets()
{
    static const QStringList list {
        QStringLiteral("x := x + 1;\n"), QStringLiteral("IF "), QStringLiteral(" THEN\n"), QStringLiteral("END_IF;\n"),
        QStringLiteral("(* comment *)"), QStringLiteral("(*"), QStringLiteral("*)"), QStringLiteral("NOT "), QStringLiteral(";"),
        QStringLiteral("\n"), QStringLiteral("LD TRUE\nST x\n"), QStringLiteral("FOR i := 1 TO 10 DO\n"), QStringLiteral("END_FOR;"),
        QStringLiteral("T#1s"), QStringLiteral("'text"), QStringLiteral("Timer(IN := TRUE, PT := T#5s);\n"), QStringLiteral("ü€"),
        QStringLiteral("CASE x OF 1: "), QStringLiteral("END_CASE"), QStringLiteral("(((("), QStringLiteral("))"),
        QStringLiteral("VAR y : INT; END_VAR\n"), QStringLiteral("\t"), QStringLiteral("16#FF"), QStringLiteral(" AND "),
    };
    return list;
}

QString randomName(QRandomGenerator &random)
{
    static const QStringList junk {QString(), QStringLiteral("1x"), QStringLiteral("END_IF"), QStringLiteral("a b"), QStringLiteral("Main"),
                                   QStringLiteral("ä"), QStringLiteral("x__y"), QStringLiteral("INT")};
    if (random.bounded(4) == 0)
        return junk[random.bounded(int(junk.size()))];
    return QStringLiteral("M%1").arg(random.bounded(1000));
}

QPlainTextEdit *editableText(QWidget *document)
{
    if (!document)
        return nullptr;
    QList<QPlainTextEdit *> editors;
    for (QPlainTextEdit *editor : document->findChildren<QPlainTextEdit *>()) {
        if (editor->isVisible() && !editor->isReadOnly())
            editors << editor;
    }
    if (auto *self = qobject_cast<QPlainTextEdit *>(document); self && !self->isReadOnly())
        editors << self;
    return editors.isEmpty() ? nullptr : editors.back(); // the body is below the declarations
}

QGraphicsView *diagramView(QWidget *document)
{
    if (!document)
        return nullptr;
    for (QGraphicsView *view : document->findChildren<QGraphicsView *>()) {
        if (view->isVisible() && view->scene())
            return view;
    }
    return nullptr;
}

} // namespace

Monkey::Monkey(iec::app::MainWindow &window, quint32 seed)
    : m_window(window)
    , m_random(seed)
    , m_answerer(new QTimer)
{
    QObject::connect(m_answerer, &QTimer::timeout, m_answerer, [this] { answerDialogs(); });
    m_answerer->start(20);
}

Monkey::~Monkey()
{
    delete m_answerer;
}

QWidget *Monkey::currentDocument() const
{
    return m_window.documents().currentWidget();
}

QList<QAction *> Monkey::documentActions() const
{
    QList<QAction *> actions;
    if (QWidget *document = currentDocument()) {
        actions = document->actions();
        actions += document->findChildren<QAction *>();
    }
    return actions;
}

QList<QAction *> Monkey::menuActions(const char *menuName) const
{
    const auto *menu = m_window.menuBar()->findChild<QMenu *>(QString::fromLatin1(menuName));
    return menu ? menu->actions() : QList<QAction *>();
}

QString Monkey::trigger(const QList<QAction *> &candidates, const QString &kind)
{
    QList<QAction *> usable;
    for (QAction *action : candidates) {
        if (action->isEnabled() && !forbidden(action) && !usable.contains(action))
            usable << action;
    }
    if (usable.isEmpty())
        return kind + QStringLiteral(": none enabled");
    QAction *action = usable[pick(int(usable.size()))];
    const QString name = action->objectName().isEmpty() ? action->text() : action->objectName();
    action->trigger();
    return kind + QLatin1Char(' ') + name;
}

QString Monkey::typeText()
{
    QPlainTextEdit *editor = editableText(currentDocument());
    if (!editor) // a diagram, or read-only while online
        return QStringLiteral("type: nothing editable");
    const QString snippet = snippets()[pick(int(snippets().size()))];
    QTextCursor cursor(editor->document());
    cursor.setPosition(pick(editor->document()->characterCount()));
    editor->setTextCursor(cursor);
    // Key clicks through the editor's key handling; QTest types printable ASCII only.
    const QString keys = snippet.left(12);
    const bool printable = std::all_of(keys.cbegin(), keys.cend(), [](QChar c) { return c.unicode() >= 0x20 && c.unicode() < 0x7f; });
    if (printable && m_random.bounded(2) == 0) {
        QTest::keyClicks(editor, keys);
        return QStringLiteral("keys %1").arg(keys.toHtmlEscaped());
    }
    editor->textCursor().insertText(snippet);
    return QStringLiteral("type %1").arg(snippet.toHtmlEscaped());
}

QString Monkey::eraseText()
{
    QPlainTextEdit *editor = editableText(currentDocument());
    if (!editor)
        return trigger(documentActions(), QStringLiteral("action"));
    const int size = editor->document()->characterCount();
    QTextCursor cursor(editor->document());
    const int from = pick(size);
    cursor.setPosition(from);
    cursor.setPosition(std::min(size - 1, from + pick(40)), QTextCursor::KeepAnchor);
    editor->setTextCursor(cursor);
    QTest::keyClick(editor, Qt::Key_Delete);
    return QStringLiteral("erase at %1").arg(from);
}

QString Monkey::clipboard()
{
    QPlainTextEdit *editor = editableText(currentDocument());
    if (!editor)
        return trigger(documentActions(), QStringLiteral("action"));
    switch (pick(3)) {
    case 0:
        editor->cut();
        return QStringLiteral("cut");
    case 1:
        editor->copy();
        return QStringLiteral("copy");
    default:
        editor->paste();
        return QStringLiteral("paste");
    }
}

QString Monkey::selectItems()
{
    QGraphicsView *view = diagramView(currentDocument());
    if (!view)
        return QStringLiteral("select: no diagram");
    QList<QGraphicsItem *> selectable;
    for (QGraphicsItem *item : view->scene()->items()) {
        if (item->flags() & QGraphicsItem::ItemIsSelectable)
            selectable << item;
    }
    view->scene()->clearSelection();
    const int count = selectable.isEmpty() ? 0 : 1 + pick(std::min(3, int(selectable.size())));
    for (int i = 0; i < count; ++i)
        selectable[pick(int(selectable.size()))]->setSelected(true);
    return QStringLiteral("select %1 of %2").arg(count).arg(selectable.size());
}

QString Monkey::zoom()
{
    QWidget *target = diagramView(currentDocument());
    if (auto *view = qobject_cast<QGraphicsView *>(target))
        target = view->viewport();
    else
        target = editableText(currentDocument());
    if (!target)
        return QStringLiteral("zoom: nothing");
    const int steps = m_random.bounded(2) ? 120 : -120;
    const QPointF at(target->width() / 2.0, target->height() / 2.0);
    QWheelEvent wheel(at, target->mapToGlobal(at), {}, {0, steps}, Qt::NoButton, Qt::ControlModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(target, &wheel);
    return QStringLiteral("zoom %1").arg(steps > 0 ? QStringLiteral("in") : QStringLiteral("out"));
}

QString Monkey::rename()
{
    // The POU of the current document, renamed from the tree as a user does (a dialog asks).
    auto *rename = m_window.findChild<QAction *>(QStringLiteral("renameAction"));
    const std::optional<iec::model::BodyRef> body = m_window.documents().currentBody();
    auto *tree = m_window.findChild<QAbstractItemView *>(QStringLiteral("projectTree"));
    if (!rename || !body || !tree)
        return QStringLiteral("rename: nothing");
    const iec::model::Pou *pou = m_window.projectModel().project().findPou(body->pou);
    const QModelIndexList found = tree->model()->match(tree->model()->index(0, 0), Qt::EditRole, pou ? pou->name : QString(), 1,
                                                       Qt::MatchExactly | Qt::MatchRecursive);
    if (found.isEmpty() || !rename->isEnabled())
        return QStringLiteral("rename: not found");
    tree->setCurrentIndex(found.front());
    rename->trigger();
    m_window.documents().setFocus();
    return QStringLiteral("rename %1").arg(pou->name);
}

void Monkey::answerDialogs()
{
    if (QWidget *popup = QApplication::activePopupWidget()) {
        popup->close();
        return;
    }
    QWidget *modal = QApplication::activeModalWidget();
    if (!modal)
        return;
    if (auto *box = qobject_cast<QMessageBox *>(modal)) {
        const QList<QAbstractButton *> buttons = box->buttons();
        if (!buttons.isEmpty())
            buttons[pick(int(buttons.size()))]->click();
        else
            box->reject();
        return;
    }
    if (auto *files = qobject_cast<QFileDialog *>(modal)) {
        files->reject();
        return;
    }
    if (auto *dialog = qobject_cast<QDialog *>(modal)) {
        for (QLineEdit *edit : dialog->findChildren<QLineEdit *>()) {
            if (edit->isVisible() && edit->isEnabled())
                edit->setText(randomName(m_random));
        }
        for (QComboBox *combo : dialog->findChildren<QComboBox *>()) {
            if (combo->isVisible() && combo->isEnabled() && combo->count() > 0)
                combo->setCurrentIndex(pick(combo->count()));
        }
        if (m_random.bounded(4) == 0)
            dialog->reject();
        else
            dialog->accept();
        return;
    }
    modal->close();
}

std::vector<Monkey::History> Monkey::histories() const
{
    std::vector<History> list;
    for (QUndoStack *stack : m_window.undoGroup().stacks())
        list.push_back({stack, stack->index()});
    for (QPlainTextEdit *editor : m_window.documents().findChildren<QPlainTextEdit *>())
        list.push_back({editor->document(), editor->document()->availableUndoSteps()});
    return list;
}

void Monkey::recordSteps(const std::vector<History> &before)
{
    std::vector<Step> steps;
    for (const History &now : histories()) {
        int then = 0; // a history that appeared started empty
        for (const History &old : before) {
            if (old.owner == now.owner)
                then = old.position;
        }
        if (now.position != then)
            steps.push_back({now.owner, now.position - then, qobject_cast<QTextDocument *>(now.owner.data()) != nullptr});
    }
    m_steps.push_back(std::move(steps));
}

QString Monkey::gesture()
{
    const std::vector<History> before = histories();
    QString did;
    const int roll = pick(100);
    if (roll < 30)
        did = trigger(documentActions(), QStringLiteral("action"));
    else if (roll < 40)
        did = trigger(menuActions("insertMenu"), QStringLiteral("insert"));
    else if (roll < 55)
        did = typeText();
    else if (roll < 60)
        did = eraseText();
    else if (roll < 65)
        did = clipboard();
    else if (roll < 75)
        did = selectItems();
    else if (roll < 83)
        did = trigger({m_window.findChild<QAction *>(QStringLiteral("undoAction"))}, QStringLiteral("undo"));
    else if (roll < 87)
        did = trigger({m_window.findChild<QAction *>(QStringLiteral("redoAction"))}, QStringLiteral("redo"));
    else if (roll < 90)
        did = zoom();
    else if (roll < 92)
        did = rename();
    else
        did = trigger(menuActions("onlineMenu"), QStringLiteral("online"));
    QCoreApplication::processEvents(); // queued work (tree rebuilds, snapshots) runs now
    recordSteps(before);
    m_log << did;
    ++m_counts[did.section(QLatin1Char(' '), 0, 0).remove(QLatin1Char(':'))];
    return did;
}

void Monkey::logout()
{
    for (QAction *action : menuActions("onlineMenu")) {
        if (action->isEnabled() && action->shortcut() == QKeySequence(Qt::CTRL | Qt::Key_F8)) // Online → Logout
            action->trigger();
    }
    QCoreApplication::processEvents();
}

bool Monkey::undoAll(QString *problem)
{
    for (auto gesture = m_steps.rbegin(); gesture != m_steps.rend(); ++gesture) {
        for (auto step = gesture->rbegin(); step != gesture->rend(); ++step) {
            if (!step->owner && step->text) {
                ++m_lostTyping;
                continue;
            }
            if (!step->owner) {
                *problem = QStringLiteral("gesture %1 changed a history that is gone (%2)")
                               .arg(m_steps.rend() - gesture)
                               .arg(m_log.value(int(m_steps.rend() - gesture) - 1));
                return false;
            }
            for (int i = 0; i < std::abs(step->delta); ++i) {
                if (auto *stack = qobject_cast<QUndoStack *>(step->owner.data()))
                    step->delta > 0 ? stack->undo() : stack->redo();
                else if (auto *text = qobject_cast<QTextDocument *>(step->owner.data()))
                    step->delta > 0 ? text->undo() : text->redo();
            }
        }
    }
    m_steps.clear();
    m_window.documents().flushEdits();
    return true;
}

QString Monkey::statistics() const
{
    QStringList parts;
    for (auto it = m_counts.cbegin(); it != m_counts.cend(); ++it)
        parts << QStringLiteral("%1 %2").arg(it.key()).arg(it.value());
    return parts.join(QStringLiteral(", "));
}

} // namespace monkey
