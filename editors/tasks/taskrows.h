#pragma once

#include "model/project.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <vector>

// The configuration editor without widgets: a resource's tasks and a task's program instances as
// rows of text and back, and the checks of a configuration with the place of each problem.
namespace iec::editors {

enum class TaskColumn { Name, Interval, Single, Priority, Watchdog };
inline constexpr int kTaskColumnCount = 5;
enum class InstanceColumn { Name, Program };
inline constexpr int kInstanceColumnCount = 2;

// One row of a table: the cells as the user sees them, and the index of the task or instance it
// came from (-1: a new row), so what the table does not show (the instances of a task, vendor
// data, documentation) stays with it when rows move.
struct TextRow {
    QStringList cells;
    int source = -1;

    bool operator==(const TextRow &) const = default;
};

[[nodiscard]] std::vector<TextRow> taskRows(const model::Resource &resource);
[[nodiscard]] std::vector<TextRow> instanceRows(const model::Task &task);

// Where a problem is: the resource (its name when task < 0), a task's cell (instance < 0) or a
// program instance's cell.
struct ConfigurationProblem {
    int resource = -1;
    int task = -1;
    int instance = -1;
    int column = 0; // a TaskColumn or InstanceColumn
    QString message;

    bool operator==(const ConfigurationProblem &) const = default;
};

// The resource with its tasks replaced by `rows` (resource index `resourceIndex` for the
// problems). A priority that is no number 0..65535 cannot be stored: it is a problem and the
// task keeps priority 0.
struct ResourceResult {
    model::Resource resource;
    std::vector<ConfigurationProblem> problems;
};
[[nodiscard]] ResourceResult resourceWithTaskRows(
    const model::Resource &resource, const std::vector<TextRow> &rows, int resourceIndex);
[[nodiscard]] model::Task taskWithInstanceRows(const model::Task &task, const std::vector<TextRow> &rows);

// Every problem of the configuration: names that are no identifiers or taken twice (resources,
// tasks and program instances of a configuration), intervals and watchdog times that are no
// durations or are 0, SINGLE variables that are no global BOOL, a task with both an interval and a
// SINGLE variable, programs that do not exist.
[[nodiscard]] std::vector<ConfigurationProblem> validateConfiguration(
    const model::Configuration &configuration, const model::Project &project);

// A task interval as the table shows it: an ISO 8601 duration from a file (PT0.01S, as PLCopen
// exports write it) as the IEC literal T#10ms; anything else as it is. A row whose interval cell
// still shows the stored value keeps the stored text.
[[nodiscard]] QString shownTime(const QString &stored);

// The watchdog time of a task (empty: none). PLCopen has no attribute for it, so it is kept in
// an addData entry of ours; the runtime does not check it yet.
[[nodiscard]] QString taskWatchdog(const model::Task &task);
void setTaskWatchdog(model::Task &task, const QString &time);
inline constexpr const char *kWatchdogAddDataName = "http://www.iecstudio.org/task-watchdog";

// The BOOL globals of the configuration and its resources (what may start a task).
[[nodiscard]] QStringList boolGlobals(const model::Configuration &configuration);
// The project's programs (what a task may run).
[[nodiscard]] QStringList programNames(const model::Project &project);
// The first name "<stem>N" (N = 1, 2, ...) not in `taken` (case-insensitive).
[[nodiscard]] QString freeName(const QStringList &taken, const QString &stem);

} // namespace iec::editors
