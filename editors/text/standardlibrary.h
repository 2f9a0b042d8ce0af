#pragma once

#include "editors/text/textlanguage.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace iec::editors {

// The static tables the text editors offer without a project: keywords, IL operators, and the
// IEC 61131-3 standard functions and function blocks with their parameters (CODESYS V2.3 set).
struct StdParameter {
    QString name;
    QString type;
};

struct StdPou {
    enum class Kind { Function, FunctionBlock };
    enum class Category {
        Arithmetic,
        Numeric,
        BitShift,
        Selection,
        Comparison,
        String,
        TypeConversion,
        Bistable,
        Edge,
        Counter,
        Timer,
        // CODESYS's Util library (and Beremiz's LOGGER)
        BcdConversion,
        BitByte,
        MathAuxiliary,
        Controller,
        SignalGenerator,
        FunctionManipulator,
        AnalogValue,
        Messages
    };

    QString name;
    Kind kind = Kind::Function;
    Category category = Category::Arithmetic;
    QList<StdParameter> inputs;
    QList<StdParameter> outputs; // function blocks
    QString returnType; // functions
    // What it does, one short sentence (QT_TRANSLATE_NOOP text; translatedDescription() shows it).
    const char *description = nullptr;
    // The library it belongs to, as the library pane groups it ("Standard", "Util", ...). New
    // libraries add their blocks to standardPous() with their name here and appear in the pane.
    QString library = QStringLiteral("Standard");

    [[nodiscard]] QString translatedDescription() const;

    // "LIMIT(MN: ANY, IN: ANY, MX: ANY) : ANY" or "TON(IN: BOOL, PT: TIME) => Q: BOOL, ET: TIME"
    [[nodiscard]] QString signature() const;
};

// An IL operator with its modifier, as RunPro's Insert > Operator lists them (LD, LDN, AND(, JMPCN ...).
struct IlOperator {
    QString text; // what is inserted
    QString base; // LD, AND, JMP ...
    QString description; // translated
};

[[nodiscard]] QString stdCategoryName(StdPou::Category category);

[[nodiscard]] const QList<StdPou> &standardPous();
[[nodiscard]] const StdPou *findStandardPou(QStringView name); // case-insensitive
[[nodiscard]] QList<IlOperator> ilOperators();
// ST operators as (text, description) pairs.
[[nodiscard]] QList<IlOperator> stOperators();
// Keywords offered by completion in a language (upper case).
[[nodiscard]] const QStringList &completionKeywords(TextLanguage language);
[[nodiscard]] const QStringList &elementaryTypeNames();

} // namespace iec::editors
