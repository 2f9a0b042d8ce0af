#pragma once

#include <QStringView>

#include <vector>

namespace iec::interp {

// The one tokenizer of IEC Studio: the compiler parses its tokens and the ST/IL editors colour
// them, so both always agree on what a piece of text is.
enum class TokenKind {
    Identifier,
    Keyword,          // IF, END_IF, VAR, PROGRAM, AND, MOD, TRUE, ... and IL operators (LD, ST, JMPC ...)
    TypeName,         // elementary type names: BOOL, INT, REAL, TIME, STRING, ...
    IntegerLiteral,   // 42, 16#FF_FF, 2#1010, INT#5, BOOL#1
    RealLiteral,      // 1.5, 1.0E-3, REAL#2.5
    TimeLiteral,      // T#1h2m3.5s, TIME#-5ms, LTIME#1ns
    DateTimeLiteral,  // D#2024-01-01, TOD#12:00:00, DT#2024-01-01-12:00:00
    StringLiteral,    // 'text' with $ escapes
    WStringLiteral,   // "text"
    DirectAddress,    // %IX0.0, %QW3, %MD10, %I*
    Operator,         // := => + - * / ** = <> < <= > >= & ( ) [ ] , ; : . ..
    Comment,          // (* ... *) (nested), // ...
    Pragma,           // { ... }
    Error,            // a character or literal the language does not allow
};

struct Token {
    TokenKind kind = TokenKind::Error;
    int offset = 0; // in the text given to the lexer
    int length = 0;
};

// What the lexer carries from one line to the next: how deep inside (* *) comments a line ends,
// and whether it ends inside a { pragma }. The editors store it per text block so that typing
// re-lexes only the lines whose starting state changed.
struct LexState {
    int commentDepth = 0;
    bool inPragma = false;

    bool operator==(const LexState &) const = default;
};

// Tokenizes `text` starting in `state`; whitespace is skipped. On return `state` is the state at
// the end of `text`.
std::vector<Token> tokenize(QStringView text, LexState &state);

// Additions for the compiler (the contract above is unchanged).

// Tokenizes a whole source text from the initial state.
std::vector<Token> tokenize(QStringView text);

// Word classes, case-insensitive: what the lexer marks as Keyword / TypeName.
bool isKeyword(QStringView word);
bool isTypeName(QStringView word);
// LD, ST, S, R, ADD, JMPC, ...: keywords in IL, but ordinary names (ADD(1, 2), Flipflop.R) in ST.
bool isIlOperator(QStringView word);

// The shape of an IEC 61131-3 identifier: a letter or '_' first, then letters, digits and single
// underscores, no '_' last. isIecIdentifier also refuses keywords and elementary type names. The
// one rule every name check of the IDE (POUs, data types, variables) uses.
bool hasIdentifierShape(QStringView word);
bool isIecIdentifier(QStringView word);

} // namespace iec::interp
