#pragma once

#include <QString>

class QGraphicsScene;
class QPrinter;

namespace iec::editors {

// Writes the scene's drawing (white background, no selection marks) as SVG, PNG or PDF, chosen
// by the file's extension. Returns an empty string or a message saying why it failed.
QString exportScene(QGraphicsScene &scene, const QString &path);
// Prints the drawing fitted to the printer's page.
void printScene(QGraphicsScene &scene, QPrinter &printer);

} // namespace iec::editors
