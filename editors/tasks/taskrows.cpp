#include "editors/tasks/taskrows.h"

#include "interpreter/compiler/lexer.h"
#include "interpreter/frontend/duration.h"
#include "interpreter/runtime/valueformat.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>

namespace iec::editors {

namespace {

// The messages' translation context.
class TaskRows
{
    Q_DECLARE_TR_FUNCTIONS(iec::editors::TaskRows)
};

bool sameName(const QString &a, const QString &b)
{
    return a.compare(b, Qt::CaseInsensitive) == 0;
}

template <typename Item>
const Item *sourceOf(const std::vector<Item> &items, int source)
{
    return source >= 0 && source < int(items.size()) ? &items[size_t(source)] : nullptr;
}

void collectBoolGlobals(const std::vector<model::VarList> &lists, QStringList &names)
{
    for (const model::VarList &list : lists) {
        for (const model::Variable &variable : list.variables) {
            const auto *elementary = std::get_if<model::ElementaryType>(&variable.type.kind);
            if (elementary && sameName(elementary->name, QStringLiteral("BOOL")))
                names << variable.name;
        }
    }
}

// The message for a time that is no duration or is 0; empty when fine. `zero` says what 0 means.
QString timeProblem(const QString &text, const char *zero)
{
    const std::optional<std::int64_t> ns = interp::frontend::parseDuration(text.trimmed());
    if (!ns)
        return TaskRows::tr("\"%1\" is not a time such as T#10ms, T#1s or 20ms.").arg(text);
    if (*ns <= 0)
        return TaskRows::tr(zero);
    return {};
}

QString nameProblem(const QString &name)
{
    if (name.trimmed().isEmpty())
        return TaskRows::tr("Enter a name.");
    // Only the shape: CODESYS and the shipped examples name resources "Resource", a keyword.
    if (!interp::hasIdentifierShape(name))
        return TaskRows::tr("\"%1\" is not a valid name: use letters, digits and single underscores.").arg(name);
    return {};
}

// Names that must be unique: the first one wins, later ones get the message.
class NameRegister
{
public:
    [[nodiscard]] bool take(const QString &name)
    {
        if (m_names.contains(name, Qt::CaseInsensitive))
            return false;
        m_names << name;
        return true;
    }

private:
    QStringList m_names;
};

void checkTask(const model::Task &task, const model::Configuration &configuration, int resource, int index,
    std::vector<ConfigurationProblem> &problems)
{
    const auto add = [&](TaskColumn column, const QString &message) {
        problems.push_back({resource, index, -1, int(column), message});
    };
    if (QString problem = nameProblem(task.name); !problem.isEmpty())
        add(TaskColumn::Name, problem);
    if (task.interval && !task.interval->trimmed().isEmpty()) {
        if (QString problem = timeProblem(*task.interval,
                QT_TRANSLATE_NOOP("iec::editors::TaskRows",
                    "A cyclic task needs an interval above 0; leave it empty for a task started by its SINGLE variable."));
            !problem.isEmpty())
            add(TaskColumn::Interval, problem);
    }
    const bool hasSingle = task.single && !task.single->trimmed().isEmpty();
    if (hasSingle && !boolGlobals(configuration).contains(task.single->trimmed(), Qt::CaseInsensitive))
        add(TaskColumn::Single, TaskRows::tr("There is no global BOOL variable %1 in this configuration.").arg(*task.single));
    // The runtime starts a task with a SINGLE variable only on its rising edge and ignores the
    // interval then; saying so beats a cyclic task that silently never runs cyclically.
    if (hasSingle && task.interval && !task.interval->trimmed().isEmpty())
        add(TaskColumn::Single,
            TaskRows::tr("A task runs either every interval or when its SINGLE variable becomes TRUE: clear the "
                         "interval or the SINGLE variable."));
    if (QString watchdog = taskWatchdog(task); !watchdog.isEmpty()) {
        if (QString problem = timeProblem(watchdog,
                QT_TRANSLATE_NOOP("iec::editors::TaskRows", "A watchdog time must be above 0; leave it empty for none."));
            !problem.isEmpty())
            add(TaskColumn::Watchdog, problem);
    }
}

// The cell's time when it is the shown form of `stored`: what the file had stays as it was when
// only another cell of the row changed.
std::optional<QString> storedTime(const QString &cell, const std::optional<QString> &stored)
{
    if (cell.isEmpty())
        return std::nullopt;
    if (stored && shownTime(*stored) == cell)
        return stored;
    return cell;
}

} // namespace

QString shownTime(const QString &stored)
{
    const QString text = stored.trimmed();
    if (!text.startsWith(QLatin1Char('P'), Qt::CaseInsensitive))
        return stored;
    const std::optional<std::int64_t> ns = interp::frontend::parseDuration(text);
    return ns ? interp::formatDuration(*ns) : stored;
}

std::vector<TextRow> taskRows(const model::Resource &resource)
{
    std::vector<TextRow> rows;
    for (int index = 0; index < int(resource.tasks.size()); ++index) {
        const model::Task &task = resource.tasks[size_t(index)];
        rows.push_back({{task.name, shownTime(task.interval.value_or(QString())), task.single.value_or(QString()),
                           QString::number(task.priority), taskWatchdog(task)},
            index});
    }
    return rows;
}

std::vector<TextRow> instanceRows(const model::Task &task)
{
    std::vector<TextRow> rows;
    for (int index = 0; index < int(task.pouInstances.size()); ++index) {
        const model::PouInstance &instance = task.pouInstances[size_t(index)];
        rows.push_back({{instance.name, instance.typeName}, index});
    }
    return rows;
}

ResourceResult resourceWithTaskRows(const model::Resource &resource, const std::vector<TextRow> &rows, int resourceIndex)
{
    ResourceResult result {resource, {}};
    result.resource.tasks.clear();
    for (int row = 0; row < int(rows.size()); ++row) {
        const QStringList &cells = rows[size_t(row)].cells;
        const model::Task *old = sourceOf(resource.tasks, rows[size_t(row)].source);
        model::Task task = old ? *old : model::Task {};
        task.name = cells.value(int(TaskColumn::Name)).trimmed();
        task.interval = storedTime(cells.value(int(TaskColumn::Interval)).trimmed(), task.interval);
        const QString single = cells.value(int(TaskColumn::Single)).trimmed();
        task.single = single.isEmpty() ? std::nullopt : std::optional(single);
        bool ok = false;
        const QString priority = cells.value(int(TaskColumn::Priority)).trimmed();
        const uint value = priority.isEmpty() ? 0 : priority.toUInt(&ok);
        if (!priority.isEmpty() && (!ok || value > 65535))
            result.problems.push_back({resourceIndex, row, -1, int(TaskColumn::Priority),
                TaskRows::tr("\"%1\" is not a priority: use a whole number from 0 (highest) to 65535.").arg(priority)});
        task.priority = ok ? value : 0;
        setTaskWatchdog(task, cells.value(int(TaskColumn::Watchdog)).trimmed());
        result.resource.tasks.push_back(std::move(task));
    }
    return result;
}

model::Task taskWithInstanceRows(const model::Task &task, const std::vector<TextRow> &rows)
{
    model::Task result = task;
    result.pouInstances.clear();
    for (const TextRow &row : rows) {
        const model::PouInstance *old = sourceOf(task.pouInstances, row.source);
        model::PouInstance instance = old ? *old : model::PouInstance {};
        instance.name = row.cells.value(int(InstanceColumn::Name)).trimmed();
        instance.typeName = row.cells.value(int(InstanceColumn::Program)).trimmed();
        result.pouInstances.push_back(std::move(instance));
    }
    return result;
}

std::vector<ConfigurationProblem> validateConfiguration(
    const model::Configuration &configuration, const model::Project &project)
{
    std::vector<ConfigurationProblem> problems;
    NameRegister resources;
    NameRegister tasks;
    NameRegister instances;
    const QStringList programs = programNames(project);
    for (int r = 0; r < int(configuration.resources.size()); ++r) {
        const model::Resource &resource = configuration.resources[size_t(r)];
        if (QString problem = nameProblem(resource.name); !problem.isEmpty())
            problems.push_back({r, -1, -1, 0, problem});
        else if (!resources.take(resource.name))
            problems.push_back({r, -1, -1, 0, TaskRows::tr("There is another resource named %1.").arg(resource.name)});
        for (int t = 0; t < int(resource.tasks.size()); ++t) {
            const model::Task &task = resource.tasks[size_t(t)];
            checkTask(task, configuration, r, t, problems);
            if (!task.name.isEmpty() && !tasks.take(task.name))
                problems.push_back({r, t, -1, int(TaskColumn::Name), TaskRows::tr("There is another task named %1.").arg(task.name)});
            for (int i = 0; i < int(task.pouInstances.size()); ++i) {
                const model::PouInstance &instance = task.pouInstances[size_t(i)];
                const auto add = [&](InstanceColumn column, const QString &message) {
                    problems.push_back({r, t, i, int(column), message});
                };
                if (QString problem = nameProblem(instance.name); !problem.isEmpty())
                    add(InstanceColumn::Name, problem);
                else if (!instances.take(instance.name))
                    add(InstanceColumn::Name, TaskRows::tr("There is another program instance named %1.").arg(instance.name));
                if (!programs.contains(instance.typeName, Qt::CaseInsensitive))
                    add(InstanceColumn::Program, TaskRows::tr("There is no program called %1.").arg(instance.typeName));
            }
        }
    }
    return problems;
}

QString taskWatchdog(const model::Task &task)
{
    static const QRegularExpression time(QStringLiteral("time=\"([^\"]*)\""));
    for (const model::AddDataEntry &entry : task.addData) {
        if (entry.name == QLatin1String(kWatchdogAddDataName))
            return time.match(entry.content).captured(1);
    }
    return {};
}

void setTaskWatchdog(model::Task &task, const QString &time)
{
    std::erase_if(task.addData, [](const model::AddDataEntry &entry) { return entry.name == QLatin1String(kWatchdogAddDataName); });
    if (time.isEmpty())
        return;
    QString escaped = time.toHtmlEscaped();
    task.addData.push_back({QString::fromLatin1(kWatchdogAddDataName), QStringLiteral("implementation"),
        QStringLiteral("<watchdog time=\"%1\"/>").arg(escaped)});
}

QStringList boolGlobals(const model::Configuration &configuration)
{
    QStringList names;
    collectBoolGlobals(configuration.globalVars, names);
    for (const model::Resource &resource : configuration.resources)
        collectBoolGlobals(resource.globalVars, names);
    return names;
}

QStringList programNames(const model::Project &project)
{
    QStringList names;
    for (const model::Pou &pou : project.types.pous) {
        if (pou.kind == model::PouKind::Program)
            names << pou.name;
    }
    return names;
}

QString freeName(const QStringList &taken, const QString &stem)
{
    for (int number = 1;; ++number) {
        const QString name = stem + QString::number(number);
        if (!taken.contains(name, Qt::CaseInsensitive))
            return name;
    }
}

} // namespace iec::editors
