#include "editors/datatypes/datatypeeditor.h"

#include "editors/datatypes/kindpages.h"
#include "editors/datatypes/messagelabel.h"
#include "interpreter/frontend/iecprinter.h"
#include "model/projectmodel.h"
#include "model/undo/datatypecommands.h"

#include <QComboBox>
#include <QFontDatabase>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QStackedWidget>
#include <QUndoStack>
#include <QVBoxLayout>

namespace iec::editors {

DataTypeEditor::DataTypeEditor(
    model::ProjectModel &projectModel, QString typeName, QUndoStack *undoStack, QWidget *parent)
    : QWidget(parent)
    , m_projectModel(projectModel)
    , m_typeName(std::move(typeName))
    , m_index(projectModel.dataTypeIndex(m_typeName))
    , m_undoStack(undoStack)
    , m_kind(new QComboBox(this))
    , m_stack(new QStackedWidget(this))
    , m_previewLabel(new QLabel(this))
    , m_preview(new QPlainTextEdit(this))
{
    auto *header = new QFormLayout;
    header->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    const CheckedField name = addCheckedField(header, tr("Name:"), this);
    m_name = name.edit;
    m_nameMessage = name.message;
    header->addRow(tr("Kind:"), m_kind);
    buildPages();

    auto *footer = new QFormLayout;
    footer->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    const CheckedField initialValue = addCheckedField(footer, tr("Initial value:"), this);
    m_initialValue = initialValue.edit;
    m_initialValueMessage = initialValue.message;
    m_initialValue->setPlaceholderText(tr("(the default of the type)"));

    m_preview->setReadOnly(true);
    m_preview->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_preview->setMaximumHeight(m_preview->fontMetrics().lineSpacing() * 10);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(header);
    layout->addWidget(m_stack, 1);
    layout->addLayout(footer);
    layout->addWidget(m_previewLabel);
    layout->addWidget(m_preview);

    connect(m_name, &QLineEdit::editingFinished, this, &DataTypeEditor::apply);
    connect(m_initialValue, &QLineEdit::editingFinished, this, &DataTypeEditor::apply);
    connect(m_kind, &QComboBox::activated, this, &DataTypeEditor::kindChosen);
    connect(&m_projectModel, &model::ProjectModel::dataTypesChanged, this, &DataTypeEditor::loadFromModel);
    connect(&m_projectModel, &model::ProjectModel::projectReset, this, [this] {
        m_index = -1; // another project: only the same name is the same type
        loadFromModel();
    });
    loadFromModel();
}

void DataTypeEditor::buildPages()
{
    // In TypeKind order: the combo index, the stack index and the kind are the same number.
    const std::array<std::pair<KindPage *, QString>, 6> pages {{
        {new StructPage(this), tr("Structure")},
        {new EnumPage(this), tr("Enumeration")},
        {new ArrayPage(this), tr("Array")},
        {new SubrangePage(this), tr("Subrange")},
        {new AliasPage(this), tr("Alias")},
        {new StringPage(this), tr("String")},
    }};
    for (size_t i = 0; i < pages.size(); ++i) {
        m_pages[i] = pages[i].first;
        m_stack->addWidget(pages[i].first);
        m_kind->addItem(pages[i].second);
        connect(pages[i].first, &KindPage::edited, this, &DataTypeEditor::apply);
    }
}

const model::DataTypeDecl *DataTypeEditor::currentDecl() const
{
    const auto &types = m_projectModel.project().types.dataTypes;
    if (const model::DataTypeDecl *byName = m_projectModel.project().findDataType(m_typeName))
        return byName;
    // Renamed (here, or by an undo): the type keeps its place and has a name no other type had.
    if (m_index >= 0 && size_t(m_index) < types.size()
        && !m_otherNames.contains(types[size_t(m_index)].name, Qt::CaseInsensitive))
        return &types[size_t(m_index)];
    return nullptr;
}

DataTypeForm DataTypeEditor::form() const
{
    DataTypeForm form;
    form.name = m_name->text();
    form.kind = TypeKind(m_kind->currentIndex());
    m_pages[size_t(form.kind)]->store(form);
    form.initialValue = m_initialValue->text();
    return form;
}

void DataTypeEditor::loadFromModel()
{
    const model::DataTypeDecl *decl = currentDecl();
    if (!decl) {
        if (m_present) {
            m_present = false;
            setEnabled(false);
            Q_EMIT typeRemoved();
        }
        return;
    }
    m_present = true;
    setEnabled(true);
    m_index = m_projectModel.dataTypeIndex(decl->name);
    m_otherNames = typeContext(m_projectModel.project(), decl->name).takenNames;
    if (decl->name != m_typeName) {
        m_typeName = decl->name;
        Q_EMIT typeRenamed(m_typeName);
    }
    m_errors.clear();
    loadForm(formFromDecl(*decl));
    showErrors();
    m_preview->setPlainText(interp::frontend::printTypeDeclaration(*decl));
}

void DataTypeEditor::loadForm(const DataTypeForm &form)
{
    m_name->setText(form.name);
    m_kind->setCurrentIndex(int(form.kind));
    m_stack->setCurrentIndex(int(form.kind));
    m_pages[size_t(form.kind)]->load(form);
    m_initialValue->setText(form.initialValue);
}

void DataTypeEditor::kindChosen(int index)
{
    const model::DataTypeDecl *decl = currentDecl();
    if (!decl)
        return;
    // The new kind's fields start from small defaults; the name and initial value stay as typed.
    DataTypeForm switched = formFromDecl(*decl);
    switched.name = m_name->text();
    switched.initialValue = m_initialValue->text();
    loadForm(withKind(switched, TypeKind(index)));
    apply();
}

void DataTypeEditor::apply()
{
    const model::DataTypeDecl *decl = currentDecl();
    if (!decl)
        return;
    const DataTypeForm edited = form();
    m_errors = DataTypeValidator::validate(edited, typeContext(m_projectModel.project(), decl->name));
    showErrors();
    if (!m_errors.empty())
        return;
    const std::optional<model::DataTypeDecl> changed = declFromForm(edited, *decl);
    if (!changed || *changed == *decl)
        return;
    // A gesture is its own undo step: the parent keeps the stack from merging it into the edit
    // before (ChangeDataTypeCommand merges, for renames typed in the tree).
    auto *step = new QUndoCommand;
    const auto *command = new model::ChangeDataTypeCommand(m_projectModel, decl->name, *changed, step);
    step->setText(command->text());
    // Renamed members take their uses along, in the same step.
    const std::vector<model::VariableRename> renames = model::renamedMembers(decl->baseType, changed->baseType);
    if (!renames.empty() && m_renameMembers) {
        m_renameMembers(decl->name, renames, step);
        step->setText(renames.size() == 1
                ? tr("Rename member %1 to %2").arg(renames.front().oldName, renames.front().newName)
                : tr("Rename %n member(s)", nullptr, int(renames.size())));
    }
    // A rename is noticed by loadFromModel (the type keeps its place), which emits typeRenamed.
    if (m_undoStack) {
        m_undoStack->push(step);
    } else {
        step->redo();
        delete step;
    }
}

void DataTypeEditor::showErrors()
{
    m_nameMessage->showErrors(m_errors, FormField::Name);
    m_initialValueMessage->showErrors(m_errors, FormField::InitialValue);
    for (KindPage *page : m_pages)
        page->showErrors(m_errors);
    // The preview shows the model; say so while the fields hold an edit that was not applied.
    m_previewLabel->setText(
        m_errors.empty() ? tr("IEC text:") : tr("IEC text as last applied (correct the marked fields to apply):"));
}

} // namespace iec::editors
