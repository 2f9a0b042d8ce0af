#pragma once

#include <QList>
#include <QString>

namespace iec::app {

// Help → Examples: the projects of resources/examples, compiled into the program as Qt resources
// under :/examples, so they are there wherever the program is installed.
struct Example {
    QString resourcePath; // ":/examples/first_steps.xml"
    QString title; // "First steps" (the project's name, or the file name)
};

class Examples
{
public:
    // Sorted by title.
    [[nodiscard]] static QList<Example> list();
};

} // namespace iec::app
