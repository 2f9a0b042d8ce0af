#pragma once

#include "model/body.h"
#include "model/element.h"

#include <QList>
#include <QPointF>
#include <QRectF>
#include <QString>

// How an SFC chart is measured and drawn: sizes of the element kinds, where their pins are, and
// the polyline of a wire. Pure functions shared by the layout and the scene, tested as tables.
namespace iec::editors::sfc {

inline constexpr double kMargin = 20;
inline constexpr double kStepHeight = 32;
inline constexpr double kStepMinWidth = 80;
inline constexpr double kTransitionWidth = 24;
inline constexpr double kTransitionHeight = 4;
inline constexpr double kJumpWidth = 20;
inline constexpr double kJumpHeight = 14;
inline constexpr double kGap = 18;          // vertical space between consecutive elements
inline constexpr double kBranchGap = 30;    // horizontal space between branches
inline constexpr double kActionOffset = 24; // from the step's right border to its action block
inline constexpr double kActionRow = 20;
inline constexpr double kQualifierWidth = 36;
inline constexpr double kLabelGap = 8;      // from a transition or jump to its text
inline constexpr double kLabelHeight = 18;  // the row a transition's condition or a jump's target is drawn in
inline constexpr double kSelectionBarHeight = 1;
inline constexpr double kParallelBarHeight = 4; // two lines

// The width of a text in the chart font (DejaVu Sans, 12 px), from its glyph advances.
double textWidth(const QString &text);
double stepWidth(const QString &name);

// The text shown right of a transition: its inline condition (first line), the name of its
// transition part, "NOT x" when negated, empty when the condition is wired.
QString conditionText(const model::Transition &transition);
// What is drawn right of a transition: its condition text, "(2) " before it when it has a priority.
QString transitionLabel(const model::Transition &transition);
// Where a transition's label or a jump's target is drawn (empty for other elements), and the
// element's frame together with it: what must not overlap the neighbouring branch.
QRectF labelRect(const model::Element &element);
QRectF drawnRect(const model::Element &element);
// How wide a label starting at `label`'s left may be before it runs into one of the `obstacles`
// (frames of other elements, bounding boxes of wire segments) that share its row; -1 when
// nothing is in the way.
double labelRoom(const QRectF &label, const QList<QRectF> &obstacles);
// Widths of the action block's columns (qualifier and time | action | indicator).
struct ActionBlockColumns {
    double qualifier = kQualifierWidth;
    double name = 80;
    double indicator = 0;
    [[nodiscard]] double total() const { return qualifier + name + indicator; }
};
ActionBlockColumns actionBlockColumns(const model::ActionBlock &block);
QString qualifierText(const model::ActionBlockAction &action); // "N", "L T#5s"
QString actionName(const model::ActionBlockAction &action);    // the reference, or "(inline)"

// The size an element is drawn with (its own width/height when it has them).
QRectF elementRect(const model::Element &element);
bool isBar(const model::Element &element); // a divergence or convergence: a horizontal line
// The pins in scene coordinates: the input (top), the output (bottom).
QPointF inputPoint(const model::Element &element);
QPointF outputPoint(const model::Element &element);
// The wire from `source` to `target` as drawn (from the source's output down to the target's
// input; a bar end attaches at the other end's x, so branches meet their bars straight).
QList<QPointF> wirePolyline(const model::Element &source, const model::Element &target);

} // namespace iec::editors::sfc
