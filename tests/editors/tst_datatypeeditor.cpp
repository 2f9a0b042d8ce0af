// The data type editor: its pure parts (form <-> declaration, validation) as tables, and the widget
// driven as a user drives it, checking the exact model after redo / undo / redo.
#include "editors/datatypes/datatypeeditor.h"
#include "editors/datatypes/datatypeform.h"
#include "editors/datatypes/datatypevalidation.h"
#include "editors/datatypes/kindpages.h"
#include "editors/datatypes/messagelabel.h"
#include "editors/datatypes/rowtable.h"
#include "editors/datatypes/typetext.h"
#include "interpreter/frontend/iecprinter.h"
#include "model/projectmodel.h"
#include "model/undo/datatypecommands.h"

#include <QComboBox>
#include <QDir>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

using namespace iec;
using namespace iec::editors;

using Errors = std::vector<FormError>;
using OptionalDecl = std::optional<model::DataTypeDecl>;
using OptionalInt = std::optional<qint64>;
Q_DECLARE_METATYPE(iec::model::DataTypeDecl)
Q_DECLARE_METATYPE(iec::editors::DataTypeForm)
Q_DECLARE_METATYPE(iec::editors::TypeKind)
Q_DECLARE_METATYPE(Errors)
Q_DECLARE_METATYPE(OptionalDecl)
Q_DECLARE_METATYPE(OptionalInt)

// Readable failure messages.
namespace iec::model {
char *toString(const DataTypeDecl &type)
{
    return QTest::toString(
        interp::frontend::printTypeDeclaration(type) + QStringLiteral(" slot %1").arg(type.addDataSlot));
}
char *toString(const std::optional<DataTypeDecl> &type)
{
    return type ? toString(*type) : qstrdup("nullopt");
}
} // namespace iec::model

namespace iec::editors {
char *toString(const DataTypeForm &form)
{
    QStringList parts {form.name, QString::number(int(form.kind))};
    for (const MemberRow &row : form.members)
        parts << QStringLiteral("m(%1|%2|%3|%4|%5)")
                     .arg(row.name, row.type, row.initialValue, row.comment)
                     .arg(row.origin);
    for (const EnumRow &row : form.enumValues)
        parts << QStringLiteral("e(%1|%2)").arg(row.name, row.value);
    for (const model::Range &range : form.dimensions)
        parts << QStringLiteral("d(%1..%2)").arg(range.lower, range.upper);
    parts << form.enumBaseType << form.elementType << form.baseType << form.range.lower << form.range.upper
          << QString::number(form.wideString) << form.stringLength << form.initialValue;
    return QTest::toString(parts.join(QLatin1Char(';')));
}
char *toString(const std::vector<FormError> &errors)
{
    QStringList parts;
    for (const FormError &error : errors)
        parts << QStringLiteral("%1/%2: %3").arg(int(error.field)).arg(error.row).arg(error.message);
    return QTest::toString(parts.join(QLatin1Char('\n')));
}
} // namespace iec::editors

namespace {

// ---- model values

model::DataType elementary(const QString &name)
{
    return {model::ElementaryType {name}};
}

model::DataType derived(const QString &name)
{
    return {model::DerivedType {name, {}, {}}};
}

model::Value simple(const QString &text)
{
    return {model::SimpleValue {text}};
}

model::Variable member(
    const QString &name, model::DataType type, std::optional<QString> initial = {}, std::optional<QString> comment = {})
{
    model::Variable variable;
    variable.name = name;
    variable.type = std::move(type);
    if (initial)
        variable.initialValue = simple(*initial);
    if (comment)
        variable.documentation = model::FormattedText {*comment, {}};
    return variable;
}

model::DataTypeDecl decl(const QString &name, model::DataType type, std::optional<QString> initial = {})
{
    model::DataTypeDecl result;
    result.name = name;
    result.baseType = std::move(type);
    if (initial)
        result.initialValue = simple(*initial);
    return result;
}

model::DataTypeDecl pointStruct()
{
    model::StructType type;
    type.members = {member(QStringLiteral("x"), elementary(QStringLiteral("REAL"))),
        member(QStringLiteral("y"), elementary(QStringLiteral("REAL")), QStringLiteral("1.5"), QStringLiteral("up"))};
    return decl(QStringLiteral("Point"), {type});
}

model::DataTypeDecl colorEnum()
{
    model::EnumType type;
    type.values
        = {{QStringLiteral("Red"), {}}, {QStringLiteral("Green"), QStringLiteral("5")}, {QStringLiteral("Blue"), {}}};
    type.baseType = model::Box<model::DataType>(elementary(QStringLiteral("INT")));
    return decl(QStringLiteral("Color"), {type}, QStringLiteral("Green"));
}

model::DataTypeDecl bufferArray()
{
    model::ArrayType type;
    type.dimensions = {{QStringLiteral("1"), QStringLiteral("10")}, {QStringLiteral("0"), QStringLiteral("2")}};
    type.baseType = model::Box<model::DataType>(elementary(QStringLiteral("INT")));
    return decl(QStringLiteral("Buffer"), {type});
}

model::DataTypeDecl percentSubrange()
{
    return decl(QStringLiteral("Percent"),
        {model::SubrangeType {false, {QStringLiteral("0"), QStringLiteral("100")},
            model::Box<model::DataType>(elementary(QStringLiteral("INT")))}},
        QStringLiteral("50"));
}

model::DataTypeDecl speedAlias()
{
    return decl(QStringLiteral("Speed"), elementary(QStringLiteral("REAL")));
}

model::DataTypeDecl labelString()
{
    return decl(QStringLiteral("Label"), {model::StringType {false, QStringLiteral("20")}});
}

// ---- forms

DataTypeForm pointForm()
{
    DataTypeForm form;
    form.name = QStringLiteral("Point");
    form.kind = TypeKind::Struct;
    form.members = {{QStringLiteral("x"), QStringLiteral("REAL"), {}, {}, 0},
        {QStringLiteral("y"), QStringLiteral("REAL"), QStringLiteral("1.5"), QStringLiteral("up"), 1}};
    return form;
}

DataTypeForm colorForm()
{
    DataTypeForm form;
    form.name = QStringLiteral("Color");
    form.kind = TypeKind::Enum;
    form.enumValues
        = {{QStringLiteral("Red"), {}}, {QStringLiteral("Green"), QStringLiteral("5")}, {QStringLiteral("Blue"), {}}};
    form.enumBaseType = QStringLiteral("INT");
    form.initialValue = QStringLiteral("Green");
    return form;
}

DataTypeForm bufferForm()
{
    DataTypeForm form;
    form.name = QStringLiteral("Buffer");
    form.kind = TypeKind::Array;
    form.dimensions = {{QStringLiteral("1"), QStringLiteral("10")}, {QStringLiteral("0"), QStringLiteral("2")}};
    form.elementType = QStringLiteral("INT");
    return form;
}

DataTypeForm percentForm()
{
    DataTypeForm form;
    form.name = QStringLiteral("Percent");
    form.kind = TypeKind::Subrange;
    form.baseType = QStringLiteral("INT");
    form.range = {QStringLiteral("0"), QStringLiteral("100")};
    form.initialValue = QStringLiteral("50");
    return form;
}

DataTypeForm speedForm()
{
    DataTypeForm form;
    form.name = QStringLiteral("Speed");
    form.kind = TypeKind::Alias;
    form.baseType = QStringLiteral("REAL");
    return form;
}

DataTypeForm labelForm()
{
    DataTypeForm form;
    form.name = QStringLiteral("Label");
    form.kind = TypeKind::String;
    form.stringLength = QStringLiteral("20");
    return form;
}

template<typename Change> DataTypeForm changed(DataTypeForm form, Change change)
{
    change(form);
    return form;
}

template<typename Change> model::DataTypeDecl changed(model::DataTypeDecl value, Change change)
{
    change(value);
    return value;
}

model::StructType &structOf(model::DataTypeDecl &value)
{
    return std::get<model::StructType>(value.baseType.kind);
}

// The project the widget tests edit: every kind once, a program and a function block.
model::Project sampleProject()
{
    model::Project project;
    project.types.dataTypes
        = {pointStruct(), colorEnum(), bufferArray(), percentSubrange(), speedAlias(), labelString()};
    model::Pou main;
    main.name = QStringLiteral("Main");
    model::Pou motor;
    motor.name = QStringLiteral("Motor");
    motor.kind = model::PouKind::FunctionBlock;
    project.types.pous = {main, motor};
    return project;
}

TypeContext sampleContext(const QString &name)
{
    return typeContext(sampleProject(), name);
}

// Commits text into a line edit as a user does: type it, press Enter.
void typeInto(QLineEdit *edit, const QString &text)
{
    edit->selectAll();
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
}

void clickButton(QWidget *parent, const QString &text)
{
    for (QToolButton *button : parent->findChildren<QToolButton *>()) {
        if (button->text() == text) {
            button->click();
            return;
        }
    }
    QFAIL(qPrintable(QStringLiteral("no button %1").arg(text)));
}

const model::DataTypeDecl &modelType(const model::ProjectModel &model, int index)
{
    return model.project().types.dataTypes[size_t(index)];
}

} // namespace

class TestDataTypeEditor : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void formFromDecl_data();
    void formFromDecl();
    void roundTripKeepsEverything_data();
    void roundTripKeepsEverything();
    void declFromForm_data();
    void declFromForm();
    void validate_data();
    void validate();
    void withKind_data();
    void withKind();
    void integerLiteral_data();
    void integerLiteral();

    void changeMemberTypeIsOneCommand();
    void addEnumValue();
    void moveAndRemoveMembers();
    void invalidArrayBoundsShowMessageAndKeepModel();
    void renameFollowsUndoAndRedo();
    void chooseKindAppliesDefaults();
    void modelChangeRefreshesForm();
    void withoutStackAppliesDirectly();
    void removedTypeDisablesEditor();
    void grabForLooking();
};

// ---- pure: conversions

void TestDataTypeEditor::formFromDecl_data()
{
    QTest::addColumn<model::DataTypeDecl>("decl");
    QTest::addColumn<DataTypeForm>("form");
    QTest::newRow("struct") << pointStruct() << pointForm();
    QTest::newRow("enum") << colorEnum() << colorForm();
    QTest::newRow("array") << bufferArray() << bufferForm();
    QTest::newRow("subrange") << percentSubrange() << percentForm();
    QTest::newRow("alias") << speedAlias() << speedForm();
    QTest::newRow("string") << labelString() << labelForm();
    QTest::newRow("derived alias") << decl(QStringLiteral("Place"), derived(QStringLiteral("Point")))
                                   << changed(speedForm(), [](DataTypeForm &f) {
                                          f.name = QStringLiteral("Place");
                                          f.baseType = QStringLiteral("Point");
                                      });
}

void TestDataTypeEditor::formFromDecl()
{
    QFETCH(model::DataTypeDecl, decl);
    QFETCH(DataTypeForm, form);
    QCOMPARE(editors::formFromDecl(decl), form);
}

void TestDataTypeEditor::roundTripKeepsEverything_data()
{
    QTest::addColumn<model::DataTypeDecl>("decl");
    QTest::newRow("struct") << pointStruct();
    QTest::newRow("enum") << colorEnum();
    QTest::newRow("array") << bufferArray();
    QTest::newRow("subrange") << percentSubrange();
    QTest::newRow("alias") << speedAlias();
    QTest::newRow("string") << labelString();
    // What the form does not show survives an untouched field.
    QTest::newRow("vendor data") << changed(pointStruct(), [](model::DataTypeDecl &d) {
        d.addDataSlot = 3;
        d.documentation = model::FormattedText {QStringLiteral("a point"), {}};
        structOf(d).members[0].type
            = {model::DerivedType {QStringLiteral("Motor"), {}, {{{QStringLiteral("a"), QStringLiteral("b")}}, {}}}};
        structOf(d).members[0].address = QStringLiteral("%MW0");
    });
    // The parser has no pointer syntax: an untouched pointer alias must stay a pointer.
    QTest::newRow("pointer") << decl(
        QStringLiteral("Ref"), {model::PointerType {model::Box<model::DataType>(elementary(QStringLiteral("INT")))}});
}

void TestDataTypeEditor::roundTripKeepsEverything()
{
    QFETCH(model::DataTypeDecl, decl);
    QCOMPARE(editors::declFromForm(editors::formFromDecl(decl), decl), OptionalDecl(decl));
}

void TestDataTypeEditor::declFromForm_data()
{
    QTest::addColumn<DataTypeForm>("form");
    QTest::addColumn<model::DataTypeDecl>("original");
    QTest::addColumn<OptionalDecl>("expected");

    QTest::newRow("member type") << changed(pointForm(), [](DataTypeForm &f) {
        f.members[0].type = QStringLiteral("dint");
    }) << pointStruct() << OptionalDecl(changed(pointStruct(), [](model::DataTypeDecl &d) {
        structOf(d).members[0].type = elementary(QStringLiteral("DINT"));
    }));
    QTest::newRow("member array type and value") << changed(pointForm(), [](DataTypeForm &f) {
        f.members[1].type = QStringLiteral("ARRAY[1..2] OF BOOL");
        f.members[1].initialValue = QStringLiteral("[TRUE, FALSE]");
    }) << pointStruct() << OptionalDecl(changed(pointStruct(), [](model::DataTypeDecl &d) {
        model::ArrayType array {{{QStringLiteral("1"), QStringLiteral("2")}},
            model::Box<model::DataType>(elementary(QStringLiteral("BOOL")))};
        structOf(d).members[1].type = {array};
        model::ArrayValue value;
        value.values = {{{}, model::Box<model::Value>(simple(QStringLiteral("TRUE")))},
            {{}, model::Box<model::Value>(simple(QStringLiteral("FALSE")))}};
        structOf(d).members[1].initialValue = model::Value {value};
    }));
    QTest::newRow("members moved and added") << changed(pointForm(), [](DataTypeForm &f) {
        std::swap(f.members[0], f.members[1]);
        f.members.push_back({QStringLiteral("z"), QStringLiteral("Point"), {}, QStringLiteral("depth"), -1});
    }) << pointStruct() << OptionalDecl(changed(pointStruct(), [](model::DataTypeDecl &d) {
        auto &members = structOf(d).members;
        std::swap(members[0], members[1]);
        members.push_back(member(QStringLiteral("z"), derived(QStringLiteral("Point")), {}, QStringLiteral("depth")));
    }));
    QTest::newRow("enum value without base") << changed(colorForm(), [](DataTypeForm &f) {
        f.enumValues.push_back({QStringLiteral("Black"), QStringLiteral("9")});
        f.enumBaseType.clear();
    }) << colorEnum() << OptionalDecl(changed(colorEnum(), [](model::DataTypeDecl &d) {
        auto &type = std::get<model::EnumType>(d.baseType.kind);
        type.values.push_back({QStringLiteral("Black"), QStringLiteral("9")});
        type.baseType.reset();
    }));
    QTest::newRow("array bounds trimmed") << changed(bufferForm(), [](DataTypeForm &f) {
        f.dimensions[0] = {QStringLiteral(" 0"), QStringLiteral("9 ")};
    }) << bufferArray() << OptionalDecl(changed(bufferArray(), [](model::DataTypeDecl &d) {
        std::get<model::ArrayType>(d.baseType.kind).dimensions[0] = {QStringLiteral("0"), QStringLiteral("9")};
    }));
    QTest::newRow("unsigned subrange") << changed(percentForm(), [](DataTypeForm &f) {
        f.baseType = QStringLiteral("UINT");
    }) << percentSubrange() << OptionalDecl(changed(percentSubrange(), [](model::DataTypeDecl &d) {
        auto &type = std::get<model::SubrangeType>(d.baseType.kind);
        type.isUnsigned = true;
        type.baseType = model::Box<model::DataType>(elementary(QStringLiteral("UINT")));
    }));
    QTest::newRow("wide string, no length") << changed(labelForm(), [](DataTypeForm &f) {
        f.wideString = true;
        f.stringLength.clear();
    }) << labelString() << OptionalDecl(decl(QStringLiteral("Label"), {model::StringType {true, {}}}));
    QTest::newRow("renamed, initial value removed") << changed(percentForm(), [](DataTypeForm &f) {
        f.name = QStringLiteral(" Ratio ");
        f.initialValue.clear();
    }) << percentSubrange() << OptionalDecl(changed(percentSubrange(), [](model::DataTypeDecl &d) {
        d.name = QStringLiteral("Ratio");
        d.initialValue.reset();
    }));
    QTest::newRow("kind changed") << editors::withKind(speedForm(), TypeKind::Array) << speedAlias()
                                  << OptionalDecl(decl(QStringLiteral("Speed"),
                                         {model::ArrayType {{{QStringLiteral("1"), QStringLiteral("10")}},
                                             model::Box<model::DataType>(elementary(QStringLiteral("REAL")))}}));
    QTest::newRow("type does not parse") << changed(pointForm(), [](DataTypeForm &f) {
        f.members[0].type = QStringLiteral("ARRAY OF");
    }) << pointStruct() << OptionalDecl();
    QTest::newRow("value does not parse")
        << changed(pointForm(), [](DataTypeForm &f) { f.initialValue = QStringLiteral("(x := "); }) << pointStruct()
        << OptionalDecl();
    QTest::newRow("text smuggling a second type")
        << changed(speedForm(), [](DataTypeForm &f) { f.baseType = QStringLiteral("INT; X : BOOL"); }) << speedAlias()
        << OptionalDecl();
}

void TestDataTypeEditor::declFromForm()
{
    QFETCH(DataTypeForm, form);
    QFETCH(model::DataTypeDecl, original);
    QFETCH(OptionalDecl, expected);
    QCOMPARE(editors::declFromForm(form, original), expected);
}

// ---- pure: validation

void TestDataTypeEditor::validate_data()
{
    QTest::addColumn<DataTypeForm>("form");
    QTest::addColumn<Errors>("errors");
    const auto error = [](FormField field, int row, const QString &message) { return FormError {field, row, message}; };
    const QString notIdentifier = QStringLiteral(
        "\"%1\" is not an IEC identifier: use letters, digits and single underscores, starting with a letter or an "
        "underscore and not ending with an underscore.");

    QTest::newRow("struct ok") << pointForm() << Errors {};
    QTest::newRow("enum ok") << colorForm() << Errors {};
    QTest::newRow("array ok") << bufferForm() << Errors {};
    QTest::newRow("subrange ok") << percentForm() << Errors {};
    QTest::newRow("alias ok") << speedForm() << Errors {};
    QTest::newRow("string ok") << labelForm() << Errors {};
    QTest::newRow("member of FB type ok")
        << changed(pointForm(), [](DataTypeForm &f) { f.members[0].type = QStringLiteral("ARRAY[1..2] OF Motor"); })
        << Errors {};
    QTest::newRow("array bounds from constants ok")
        << changed(bufferForm(), [](DataTypeForm &f) { f.dimensions[0].upper = QStringLiteral("MaxItems"); })
        << Errors {};

    QTest::newRow("empty name") << changed(pointForm(), [](DataTypeForm &f) { f.name.clear(); })
                                << Errors {error(FormField::Name, -1, QStringLiteral("Enter a name."))};
    QTest::newRow("bad name") << changed(pointForm(), [](DataTypeForm &f) { f.name = QStringLiteral("2D"); })
                              << Errors {error(FormField::Name, -1, notIdentifier.arg(QStringLiteral("2D")))};
    QTest::newRow("keyword name") << changed(pointForm(), [](DataTypeForm &f) {
        f.name = QStringLiteral("dint");
    }) << Errors {error(FormField::Name, -1, QStringLiteral("\"dint\" is a reserved word of IEC 61131-3."))};
    QTest::newRow("name taken by a POU") << changed(pointForm(), [](DataTypeForm &f) {
        f.name = QStringLiteral("main");
    }) << Errors {error(FormField::Name, -1, QStringLiteral("A POU or data type named \"main\" exists already."))};
    QTest::newRow("duplicate member") << changed(pointForm(), [](DataTypeForm &f) {
        f.members[1].name = QStringLiteral("X");
    }) << Errors {error(FormField::MemberName, 1, QStringLiteral("There is a member named \"X\" already."))};
    QTest::newRow("no members") << changed(pointForm(), [](DataTypeForm &f) {
        f.members.clear();
    }) << Errors {error(FormField::Members, -1, QStringLiteral("A structure needs at least one member."))};
    QTest::newRow("member type missing, unknown, self, not a type, bad value") << changed(pointForm(),
        [](DataTypeForm &f) {
            f.members[0].type.clear();
            f.members[1].type = QStringLiteral("Vector");
            f.members.push_back({QStringLiteral("next"), QStringLiteral("Point"), {}, {}, -1});
            f.members.push_back({QStringLiteral("bad"), QStringLiteral("ARRAY[1..] OF"), QStringLiteral(":="), {}, -1});
        })
                                                                               << Errors {
                                                                                      error(FormField::MemberType, 0,
                                                                                          QStringLiteral(
                                                                                              "Enter a type.")),
                                                                                      error(FormField::MemberType, 1,
                                                                                          QStringLiteral(
                                                                                              "Unknown type "
                                                                                              "\"Vector\".")),
                                                                                      error(FormField::MemberType, 2,
                                                                                          QStringLiteral(
                                                                                              "A type cannot contain "
                                                                                              "itself.")),
                                                                                      error(FormField::MemberType, 3,
                                                                                          QStringLiteral(
                                                                                              "\"ARRAY[1..] OF\" is "
                                                                                              "not a type.")),
                                                                                      error(FormField::MemberValue, 3,
                                                                                          QStringLiteral(
                                                                                              "\":=\" is not a valid "
                                                                                              "initial value."))};
    QTest::newRow("library blocks and types are known, in any case") << changed(pointForm(), [](DataTypeForm &f) {
        for (const char *type : {"TON", "ctu_dint", "BLINK", "PID", "ARRAY[0..10] OF GEN_MODE", "LOGLEVEL",
                 "HMI_BOOL", "hmi_real", "RTC"})
            f.members.push_back({QStringLiteral("m%1").arg(f.members.size()), QLatin1String(type), {}, {}, -1});
    }) << Errors {};
    QTest::newRow("a library function is not a type") << changed(pointForm(), [](DataTypeForm &f) {
        f.members[1].type = QStringLiteral("EXTRACT");
    }) << Errors {error(FormField::MemberType, 1, QStringLiteral("Unknown type \"EXTRACT\"."))};
    QTest::newRow("duplicate enum value, bad explicit value, bad base")
        << changed(colorForm(),
               [](DataTypeForm &f) {
                   f.enumValues[2].name = QStringLiteral("red");
                   f.enumValues[1].value = QStringLiteral("five");
                   f.enumBaseType = QStringLiteral("REAL");
               })
        << Errors {error(FormField::EnumValue, 1, QStringLiteral("Enter a whole number, or leave it empty.")),
               error(FormField::EnumName, 2, QStringLiteral("The value \"red\" is listed already.")),
               error(FormField::EnumBaseType, -1, QStringLiteral("Choose an integer type such as INT, DINT or UINT."))};
    QTest::newRow("no enum values") << changed(colorForm(), [](DataTypeForm &f) {
        f.enumValues.clear();
    }) << Errors {error(FormField::EnumValues, -1, QStringLiteral("An enumeration needs at least one value."))};
    QTest::newRow("array low > high, empty bound, bad bound")
        << changed(bufferForm(),
               [](DataTypeForm &f) {
                   f.dimensions[0] = {QStringLiteral("10"), QStringLiteral("1")};
                   f.dimensions[1] = {QString(), QStringLiteral("1.5")};
               })
        << Errors {
               error(FormField::DimensionHigh, 0, QStringLiteral("The upper bound 1 is less than the lower bound 10.")),
               error(FormField::DimensionLow, 1, QStringLiteral("Enter a bound.")),
               error(FormField::DimensionHigh, 1, QStringLiteral("Enter a whole number or the name of a constant."))};
    QTest::newRow("hex bounds compare as numbers")
        << changed(bufferForm(),
               [](DataTypeForm &f) {
                   f.dimensions[0] = {QStringLiteral("16#10"), QStringLiteral("15")};
               })
        << Errors {error(
               FormField::DimensionHigh, 0, QStringLiteral("The upper bound 15 is less than the lower bound 16#10."))};
    QTest::newRow("no dimensions, unknown element")
        << changed(bufferForm(),
               [](DataTypeForm &f) {
                   f.dimensions.clear();
                   f.elementType = QStringLiteral("Thing");
               })
        << Errors {error(FormField::Dimensions, -1, QStringLiteral("An array needs at least one dimension.")),
               error(FormField::ElementType, -1, QStringLiteral("Unknown type \"Thing\"."))};
    QTest::newRow("subrange of REAL, reversed")
        << changed(percentForm(),
               [](DataTypeForm &f) {
                   f.baseType = QStringLiteral("REAL");
                   f.range = {QStringLiteral("5"), QStringLiteral("-5")};
               })
        << Errors {error(FormField::BaseType, -1, QStringLiteral("Choose an integer type such as INT, DINT or UINT.")),
               error(FormField::RangeHigh, -1, QStringLiteral("The upper bound -5 is less than the lower bound 5."))};
    QTest::newRow("alias of itself") << changed(speedForm(), [](DataTypeForm &f) {
        f.baseType = QStringLiteral("SPEED");
    }) << Errors {error(FormField::BaseType, -1, QStringLiteral("A type cannot contain itself."))};
    QTest::newRow("string length 0") << changed(
        labelForm(), [](DataTypeForm &f) { f.stringLength = QStringLiteral("0"); })
                                     << Errors {error(FormField::StringLength, -1,
                                            QStringLiteral("Enter a length from 1 to 65535, or leave it empty for "
                                                           "the default."))};
}

void TestDataTypeEditor::validate()
{
    QFETCH(DataTypeForm, form);
    QFETCH(Errors, errors);
    // The context is the project with the type under its model name (the form may rename it).
    const QHash<TypeKind, QString> modelName {{TypeKind::Struct, QStringLiteral("Point")},
        {TypeKind::Enum, QStringLiteral("Color")}, {TypeKind::Array, QStringLiteral("Buffer")},
        {TypeKind::Subrange, QStringLiteral("Percent")}, {TypeKind::Alias, QStringLiteral("Speed")},
        {TypeKind::String, QStringLiteral("Label")}};
    QCOMPARE(DataTypeValidator::validate(form, sampleContext(modelName.value(form.kind))), errors);
}

void TestDataTypeEditor::withKind_data()
{
    QTest::addColumn<DataTypeForm>("form");
    QTest::addColumn<TypeKind>("kind");
    QTest::addColumn<DataTypeForm>("expected");
    QTest::newRow("same kind keeps everything") << colorForm() << TypeKind::Enum << colorForm();
    QTest::newRow("to struct") << colorForm() << TypeKind::Struct << changed(colorForm(), [](DataTypeForm &f) {
        f.kind = TypeKind::Struct;
        f.initialValue.clear();
        f.members = {{QStringLiteral("Member1"), QStringLiteral("INT"), {}, {}, -1}};
    });
    QTest::newRow("to enum") << speedForm() << TypeKind::Enum << changed(speedForm(), [](DataTypeForm &f) {
        f.kind = TypeKind::Enum;
        f.enumValues = {{QStringLiteral("Value1"), {}}};
    });
    QTest::newRow("to subrange keeps an integer base")
        << changed(speedForm(), [](DataTypeForm &f) { f.baseType = QStringLiteral("UINT"); }) << TypeKind::Subrange
        << changed(speedForm(), [](DataTypeForm &f) {
               f.kind = TypeKind::Subrange;
               f.baseType = QStringLiteral("UINT");
               f.range = {QStringLiteral("0"), QStringLiteral("100")};
           });
    QTest::newRow("REAL alias to subrange of INT")
        << speedForm() << TypeKind::Subrange << changed(speedForm(), [](DataTypeForm &f) {
               f.kind = TypeKind::Subrange;
               f.baseType = QStringLiteral("INT");
               f.range = {QStringLiteral("0"), QStringLiteral("100")};
           });
    QTest::newRow("to alias") << labelForm() << TypeKind::Alias << changed(labelForm(), [](DataTypeForm &f) {
        f.kind = TypeKind::Alias;
        f.baseType = QStringLiteral("INT");
    });
    QTest::newRow("to string") << percentForm() << TypeKind::String << changed(percentForm(), [](DataTypeForm &f) {
        f.kind = TypeKind::String;
        f.initialValue.clear();
    });
}

void TestDataTypeEditor::withKind()
{
    QFETCH(DataTypeForm, form);
    QFETCH(TypeKind, kind);
    QFETCH(DataTypeForm, expected);
    QCOMPARE(editors::withKind(form, kind), expected);
}

void TestDataTypeEditor::integerLiteral_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<OptionalInt>("value");
    QTest::newRow("decimal") << QStringLiteral("42") << OptionalInt(42);
    QTest::newRow("negative") << QStringLiteral("-7") << OptionalInt(-7);
    QTest::newRow("underscores") << QStringLiteral("1_000") << OptionalInt(1000);
    QTest::newRow("hex") << QStringLiteral("16#FF") << OptionalInt(255);
    QTest::newRow("binary") << QStringLiteral("2#1010") << OptionalInt(10);
    QTest::newRow("octal") << QStringLiteral("8#17") << OptionalInt(15);
    QTest::newRow("base 3") << QStringLiteral("3#12") << OptionalInt();
    QTest::newRow("real") << QStringLiteral("1.5") << OptionalInt();
    QTest::newRow("name") << QStringLiteral("Max") << OptionalInt();
    QTest::newRow("empty") << QString() << OptionalInt();
    QTest::newRow("double sign") << QStringLiteral("--1") << OptionalInt();
}

void TestDataTypeEditor::integerLiteral()
{
    QFETCH(QString, text);
    QFETCH(OptionalInt, value);
    QCOMPARE(editors::integerLiteral(text), value);
}

// ---- the widget

void TestDataTypeEditor::changeMemberTypeIsOneCommand()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    DataTypeEditor editor(model, QStringLiteral("Point"), &stack);
    auto *page = static_cast<StructPage *>(editor.page(TypeKind::Struct));
    QCOMPARE(editor.kindBox()->currentIndex(), int(TypeKind::Struct));

    page->members()->table()->item(0, 1)->setText(QStringLiteral("LREAL"));
    const model::DataTypeDecl after = changed(pointStruct(),
        [](model::DataTypeDecl &d) { structOf(d).members[0].type = elementary(QStringLiteral("LREAL")); });
    QCOMPARE(stack.count(), 1);
    QCOMPARE(stack.command(0)->childCount(), 1);
    QVERIFY(dynamic_cast<const model::ChangeDataTypeCommand *>(stack.command(0)->child(0)));
    QCOMPARE(modelType(model, 0), after);
    QVERIFY(editor.errors().empty());
    QVERIFY(editor.preview()->toPlainText().contains(QStringLiteral("x : LREAL;")));

    stack.undo();
    QCOMPARE(modelType(model, 0), pointStruct());
    QCOMPARE(page->members()->table()->item(0, 1)->text(), QStringLiteral("REAL"));
    stack.redo();
    QCOMPARE(modelType(model, 0), after);
    QCOMPARE(page->members()->table()->item(0, 1)->text(), QStringLiteral("LREAL"));
}

void TestDataTypeEditor::addEnumValue()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    DataTypeEditor editor(model, QStringLiteral("Color"), &stack);
    auto *page = static_cast<EnumPage *>(editor.page(TypeKind::Enum));
    QTableWidget *table = page->values()->table();

    table->setCurrentCell(2, 0);
    clickButton(page, QStringLiteral("Add"));
    // A new row has no name yet: a message, no command.
    QCOMPARE(table->rowCount(), 4);
    QCOMPARE(stack.count(), 0);
    QVERIFY(page->values()->messageLabel()->isVisibleTo(&editor));
    QCOMPARE(page->values()->messageLabel()->text(), QStringLiteral("Row 4, Name: Enter a name."));

    table->item(3, 0)->setText(QStringLiteral("Black"));
    table->item(3, 1)->setText(QStringLiteral("8"));
    const model::DataTypeDecl after = changed(colorEnum(), [](model::DataTypeDecl &d) {
        std::get<model::EnumType>(d.baseType.kind).values.push_back({QStringLiteral("Black"), QStringLiteral("8")});
    });
    QCOMPARE(stack.count(), 2); // the name, then the value: two gestures
    QCOMPARE(modelType(model, 1), after);
    QVERIFY(!page->values()->messageLabel()->isVisibleTo(&editor));

    stack.undo();
    stack.undo();
    QCOMPARE(modelType(model, 1), colorEnum());
    QCOMPARE(table->rowCount(), 3);
    stack.redo();
    stack.redo();
    QCOMPARE(modelType(model, 1), after);
    QCOMPARE(table->item(3, 0)->text(), QStringLiteral("Black"));
}

void TestDataTypeEditor::moveAndRemoveMembers()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    DataTypeEditor editor(model, QStringLiteral("Point"), &stack);
    auto *page = static_cast<StructPage *>(editor.page(TypeKind::Struct));
    QTableWidget *table = page->members()->table();

    table->setCurrentCell(1, 0);
    clickButton(page, QStringLiteral("Up"));
    const model::DataTypeDecl moved = changed(
        pointStruct(), [](model::DataTypeDecl &d) { std::swap(structOf(d).members[0], structOf(d).members[1]); });
    QCOMPARE(modelType(model, 0), moved); // y moved with its initial value and comment
    QCOMPARE(table->currentRow(), 0);

    clickButton(page, QStringLiteral("Remove"));
    const model::DataTypeDecl removed = changed(
        pointStruct(), [](model::DataTypeDecl &d) { structOf(d).members.erase(structOf(d).members.begin() + 1); });
    QCOMPARE(modelType(model, 0), removed);

    // The last member cannot go: a message, and the model keeps it.
    table->setCurrentCell(0, 0);
    clickButton(page, QStringLiteral("Remove"));
    QCOMPARE(modelType(model, 0), removed);
    QCOMPARE(page->members()->messageLabel()->text(), QStringLiteral("A structure needs at least one member."));

    QCOMPARE(stack.count(), 2);
    stack.undo();
    QCOMPARE(modelType(model, 0), moved);
    QCOMPARE(table->rowCount(), 2);
    stack.undo();
    QCOMPARE(modelType(model, 0), pointStruct());
    stack.redo();
    stack.redo();
    QCOMPARE(modelType(model, 0), removed);
}

void TestDataTypeEditor::invalidArrayBoundsShowMessageAndKeepModel()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    DataTypeEditor editor(model, QStringLiteral("Buffer"), &stack);
    auto *page = static_cast<ArrayPage *>(editor.page(TypeKind::Array));
    const quint64 revision = model.revision();

    page->dimensions()->table()->item(0, 0)->setText(QStringLiteral("20"));
    QCOMPARE(model.revision(), revision);
    QCOMPARE(stack.count(), 0);
    QCOMPARE(modelType(model, 2), bufferArray());
    QCOMPARE(page->dimensions()->messageLabel()->text(),
        QStringLiteral("Row 1, High: The upper bound 10 is less than the lower bound 20."));
    QVERIFY(page->dimensions()->messageLabel()->isVisibleTo(&editor));
    QCOMPARE(page->dimensions()->table()->item(0, 1)->toolTip(),
        QStringLiteral("The upper bound 10 is less than the lower bound 20."));
    // The preview keeps showing what the model holds, and says so.
    const auto labelShown = [&editor](const QString &text) {
        const auto labels = editor.findChildren<QLabel *>();
        return std::any_of(labels.begin(), labels.end(), [&](const QLabel *label) { return label->text() == text; });
    };
    QVERIFY(labelShown(QStringLiteral("IEC text as last applied (correct the marked fields to apply):")));
    QVERIFY(editor.preview()->toPlainText().contains(QStringLiteral("ARRAY[1..10, 0..2] OF INT")));

    // Fixing the other bound makes the form valid: one command with both edits.
    page->dimensions()->table()->item(0, 1)->setText(QStringLiteral("30"));
    QCOMPARE(stack.count(), 1);
    QVERIFY(!page->dimensions()->messageLabel()->isVisibleTo(&editor));
    QVERIFY(labelShown(QStringLiteral("IEC text:")));
    const model::DataTypeDecl after = changed(bufferArray(), [](model::DataTypeDecl &d) {
        std::get<model::ArrayType>(d.baseType.kind).dimensions[0] = {QStringLiteral("20"), QStringLiteral("30")};
    });
    QCOMPARE(modelType(model, 2), after);
    stack.undo();
    QCOMPARE(modelType(model, 2), bufferArray());
    stack.redo();
    QCOMPARE(modelType(model, 2), after);
}

void TestDataTypeEditor::renameFollowsUndoAndRedo()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    DataTypeEditor editor(model, QStringLiteral("Speed"), &stack);
    QSignalSpy renamed(&editor, &DataTypeEditor::typeRenamed);

    typeInto(editor.nameEdit(), QStringLiteral("Main"));
    QCOMPARE(stack.count(), 0);
    QCOMPARE(editor.errors(),
        Errors({{FormField::Name, -1, QStringLiteral("A POU or data type named \"Main\" exists already.")}}));

    typeInto(editor.nameEdit(), QStringLiteral("Velocity"));
    QCOMPARE(stack.count(), 1);
    QCOMPARE(modelType(model, 4), decl(QStringLiteral("Velocity"), elementary(QStringLiteral("REAL"))));
    QCOMPARE(editor.typeName(), QStringLiteral("Velocity"));
    QCOMPARE(renamed.count(), 1);

    stack.undo();
    QCOMPARE(modelType(model, 4), speedAlias());
    QCOMPARE(editor.typeName(), QStringLiteral("Speed"));
    QCOMPARE(editor.nameEdit()->text(), QStringLiteral("Speed"));
    stack.redo();
    QCOMPARE(editor.typeName(), QStringLiteral("Velocity"));
    QCOMPARE(renamed.count(), 3);
}

void TestDataTypeEditor::chooseKindAppliesDefaults()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    DataTypeEditor editor(model, QStringLiteral("Speed"), &stack);

    editor.kindBox()->setCurrentIndex(int(TypeKind::Array));
    Q_EMIT editor.kindBox()->activated(int(TypeKind::Array));
    const model::DataTypeDecl array = decl(QStringLiteral("Speed"),
        {model::ArrayType {{{QStringLiteral("1"), QStringLiteral("10")}},
            model::Box<model::DataType>(elementary(QStringLiteral("REAL")))}});
    QCOMPARE(stack.count(), 1);
    QCOMPARE(modelType(model, 4), array);
    auto *page = static_cast<ArrayPage *>(editor.page(TypeKind::Array));
    QCOMPARE(page->dimensions()->table()->rowCount(), 1);

    // A second dimension, then the element type changed with the keyboard.
    page->dimensions()->table()->setCurrentCell(0, 0);
    clickButton(page, QStringLiteral("Add"));
    typeInto(page->findChild<QLineEdit *>(), QStringLiteral("Point"));
    QCOMPARE(stack.count(), 3);
    QCOMPARE(modelType(model, 4),
        decl(QStringLiteral("Speed"),
            {model::ArrayType {
                {{QStringLiteral("1"), QStringLiteral("10")}, {QStringLiteral("1"), QStringLiteral("10")}},
                model::Box<model::DataType>(derived(QStringLiteral("Point")))}}));
    stack.undo();
    stack.undo();
    QCOMPARE(modelType(model, 4), array);
    stack.undo();
    QCOMPARE(modelType(model, 4), speedAlias());
    QCOMPARE(editor.kindBox()->currentIndex(), int(TypeKind::Alias));
}

void TestDataTypeEditor::modelChangeRefreshesForm()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    DataTypeEditor editor(model, QStringLiteral("Percent"), &stack);
    QCOMPARE(editor.form(), percentForm());

    // An invalid edit is on screen when the model changes elsewhere: the model wins.
    typeInto(editor.initialValueEdit(), QStringLiteral("(x :="));
    QVERIFY(!editor.errors().empty());
    model.changeDataType(QStringLiteral("Percent"), changed(percentSubrange(), [](model::DataTypeDecl &d) {
        std::get<model::SubrangeType>(d.baseType.kind).range.upper = QStringLiteral("200");
    }));
    QCOMPARE(editor.form(), changed(percentForm(), [](DataTypeForm &f) { f.range.upper = QStringLiteral("200"); }));
    QVERIFY(editor.errors().empty());
    QVERIFY(editor.preview()->toPlainText().contains(QStringLiteral("Percent : INT (0..200) := 50;")));
}

void TestDataTypeEditor::withoutStackAppliesDirectly()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    DataTypeEditor editor(model, QStringLiteral("Label"), nullptr);
    typeInto(editor.page(TypeKind::String)->findChild<QLineEdit *>(), QStringLiteral("32"));
    QCOMPARE(modelType(model, 5), decl(QStringLiteral("Label"), {model::StringType {false, QStringLiteral("32")}}));
}

void TestDataTypeEditor::removedTypeDisablesEditor()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    DataTypeEditor editor(model, QStringLiteral("Color"), nullptr);
    QSignalSpy removed(&editor, &DataTypeEditor::typeRemoved);
    QSignalSpy renamed(&editor, &DataTypeEditor::typeRenamed);
    model.removeDataType(QStringLiteral("Point")); // another type: Color moves up a place
    QCOMPARE(removed.count(), 0);
    QVERIFY(editor.isEnabled());
    model.removeDataType(QStringLiteral("Color")); // Buffer takes its place, but it is not Color renamed
    QCOMPARE(removed.count(), 1);
    QCOMPARE(renamed.count(), 0);
    QVERIFY(!editor.isEnabled());

    // A project with the type again (a reload) brings the editor back; one without it keeps it off.
    model.reset(sampleProject());
    QVERIFY(editor.isEnabled());
    QCOMPARE(editor.form(), colorForm());
    model::Project other = sampleProject();
    other.types.dataTypes.erase(other.types.dataTypes.begin() + 1);
    model.reset(other);
    QVERIFY(!editor.isEnabled());
    QCOMPARE(removed.count(), 2);
    QCOMPARE(renamed.count(), 0);
}

// Renders the editor for a struct, an enum and an array at a fixed size; with IEC_SHOT_DIR set the
// pictures are written there for looking at.
void TestDataTypeEditor::grabForLooking()
{
    model::ProjectModel model;
    model.reset(sampleProject());
    QUndoStack stack;
    const QString directory = qEnvironmentVariable("IEC_SHOT_DIR");
    for (const QString &name : {QStringLiteral("Point"), QStringLiteral("Color"), QStringLiteral("Buffer")}) {
        DataTypeEditor editor(model, name, &stack);
        editor.resize(640, 520);
        if (name == QLatin1String("Buffer")) // show a message too
            static_cast<ArrayPage *>(editor.page(TypeKind::Array))
                ->dimensions()
                ->table()
                ->item(1, 1)
                ->setText(QStringLiteral("-1"));
        editor.show();
        const QImage image = editor.grab().toImage();
        QCOMPARE(image.size(), QSize(640, 520) * image.devicePixelRatio());
        if (!directory.isEmpty())
            QVERIFY(image.save(QDir(directory).filePath(name.toLower() + QStringLiteral(".png"))));
    }
}

QTEST_MAIN(TestDataTypeEditor)
#include "tst_datatypeeditor.moc"
