// The document area's tabs for methods, properties and interfaces (DocumentArea members kept apart from the
// body editors in documentarea.cpp).

#include "app/documentarea.h"

#include "app/interfaceeditor.h"
#include "app/membereditor.h"
#include "app/treeicons.h"
#include "editors/text/codeeditor.h"
#include "interpreter/frontend/codesysmembers.h"
#include "model/projectmodel.h"

#include <QTextDocument>

#include <algorithm>

namespace iec::app {

MemberEditor *DocumentArea::memberEditorFor(model::PouId pou, const QString &name) const
{
    for (int index = 0; index < count(); ++index) {
        auto *editor = qobject_cast<MemberEditor *>(widget(index));
        if (editor && editor->pou() == pou && editor->name().compare(name, Qt::CaseInsensitive) == 0)
            return editor;
    }
    return nullptr;
}

QWidget *DocumentArea::openMember(model::PouId pou, const QString &name)
{
    if (MemberEditor *open = memberEditorFor(pou, name)) {
        setCurrentWidget(open);
        return open;
    }
    const model::Pou *found = m_projectModel.project().findPou(pou);
    if (!found
        || std::ranges::none_of(interp::frontend::codesysMembers(*found), [&](const interp::frontend::CodesysMemberSummary &m) {
               return m.name.compare(name, Qt::CaseInsensitive) == 0;
           }))
        return nullptr;
    return addAddDataTab(new MemberEditor(m_projectModel, pou, name));
}

QWidget *DocumentArea::openInterface(const QString &name)
{
    for (int index = 0; index < count(); ++index) {
        auto *open = qobject_cast<InterfaceEditor *>(widget(index));
        if (open && open->name().compare(name, Qt::CaseInsensitive) == 0) {
            setCurrentWidget(open);
            return open;
        }
    }
    const QStringList names = interp::frontend::codesysInterfaceNames(m_projectModel.project());
    if (!names.contains(name, Qt::CaseInsensitive))
        return nullptr;
    return addAddDataTab(new InterfaceEditor(m_projectModel, name));
}

QWidget *DocumentArea::addAddDataTab(AddDataTextEditor *editor)
{
    editor->setProperty(kWholeTabEditorProperty, true); // online, its text is only looked at
    connect(editor, &AddDataTextEditor::titleChanged, this, [this, editor] {
        if (const int index = indexOf(editor); index >= 0)
            setTabText(index, editor->title());
    });
    // Queued: the editor is inside its own slot when it reports the removal.
    connect(editor, &AddDataTextEditor::removed, editor, [this, editor] {
        if (const int index = indexOf(editor); index >= 0)
            closeDocument(index);
    }, Qt::QueuedConnection);
    connect(editor->editor()->document(), &QTextDocument::modificationChanged, this, &DocumentArea::typingModifiedChanged);
    const int index = addTab(editor, languageIcon(editors::EditorLanguage::ST), editor->title());
    if (m_editingLocked)
        setEditingLocked(true);
    setCurrentIndex(index);
    return editor;
}

} // namespace iec::app
