#pragma once

#include "model/elements_fbd.h"

#include <QGraphicsView>
#include <QHash>
#include <QString>

#include <algorithm>
#include <utility>

class QGraphicsScene;

// What the online overlays of the data-flow languages (LD, FBD, CFC) share: which texts name
// something the runtime can read, the names of a function block instance's pins, and which part
// of a long body the views show.
namespace iec::editors {

// A variable, a member or an element with a constant index: something the runtime can read.
bool isVariablePath(const QString &text);
// Whether an IEC literal is TRUE.
bool isTrueLiteral(const QString &literal);
// A function block instance's pins, by the name the runtime knows them ("Main.T1.Q"), keyed by
// the pin's upper-case name; empty for a function (it has no instance to read).
QHash<QString, QString> instancePinNames(const model::Block &block, const QString &instance);

// The rows [first, last) of a body laid out in bands from top to bottom that any view of the
// scene shows; all of them when no view does (an export). `top(i)` and `bottom(i)` of the bands
// grow with i.
template<typename Top, typename Bottom>
std::pair<std::size_t, std::size_t> visibleBands(const QGraphicsScene &scene, std::size_t count, Top top, Bottom bottom)
{
    QRectF visible;
    for (const QGraphicsView *view : scene.views())
        visible |= view->mapToScene(view->viewport()->rect()).boundingRect();
    if (visible.isNull())
        return {0, count};
    std::size_t lo = 0;
    std::size_t hi = count;
    while (lo < hi) { // the first band that ends below the top of the view
        const std::size_t mid = (lo + hi) / 2;
        if (bottom(mid) < visible.top())
            lo = mid + 1;
        else
            hi = mid;
    }
    std::size_t last = lo;
    while (last < count && top(last) <= visible.bottom())
        ++last;
    return {lo, last};
}

} // namespace iec::editors
