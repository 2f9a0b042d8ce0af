#include "editors/tasks/configurationeditor.h"

#include "editors/datatypes/messagelabel.h"
#include "editors/datatypes/rowtable.h"
#include "editors/declarations/choicedelegate.h"
#include "model/projectmodel.h"
#include "model/undo/instancecommands.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QTableWidget>
#include <QUndoStack>
#include <QVBoxLayout>

namespace iec::editors {

namespace {

std::vector<TextRow> textRows(const std::vector<RowTable::Row> &rows)
{
    std::vector<TextRow> result;
    for (const RowTable::Row &row : rows)
        result.push_back({row.cells, row.tag});
    return result;
}

std::vector<RowTable::Row> tableRows(const std::vector<TextRow> &rows)
{
    std::vector<RowTable::Row> result;
    for (const TextRow &row : rows)
        result.push_back({row.cells, row.source});
    return result;
}

QLabel *heading(QWidget *parent)
{
    auto *label = new QLabel(parent);
    QFont font = label->font();
    font.setBold(true);
    label->setFont(font);
    return label;
}

int findConfiguration(const model::Instances &instances, const QString &name)
{
    for (int index = 0; index < int(instances.configurations.size()); ++index) {
        if (instances.configurations[size_t(index)].name.compare(name, Qt::CaseInsensitive) == 0)
            return index;
    }
    return -1;
}

} // namespace

ConfigurationEditor::ConfigurationEditor(
    model::ProjectModel &projectModel, const QString &configuration, QUndoStack &undoStack, QWidget *parent)
    : QWidget(parent)
    , m_projectModel(projectModel)
    , m_configuration(configuration)
    , m_undoStack(&undoStack)
{
    setObjectName(QStringLiteral("configurationEditor"));
    m_title = heading(this);
    m_resourceLabel = new QLabel(this);
    m_resourceBox = new QComboBox(this);
    m_resourceBox->setObjectName(QStringLiteral("resourceBox"));
    m_resourceName = new QLineEdit(this);
    m_resourceName->setObjectName(QStringLiteral("resourceName"));
    m_addResource = new QPushButton(this);
    m_removeResource = new QPushButton(this);
    m_resourceMessage = new MessageLabel(this);
    m_tasksLabel = heading(this);
    m_tasks = new RowTable(QStringList(kTaskColumnCount, QString()), this);
    m_tasks->setObjectName(QStringLiteral("taskTable"));
    // An empty first choice clears the variable (the task runs cyclically again).
    m_tasks->table()->setItemDelegateForColumn(int(TaskColumn::Single), new ChoiceDelegate([this] {
        const model::Configuration *configuration = current();
        return QStringList {QString()} + (configuration ? boolGlobals(*configuration) : QStringList {});
    }, m_tasks->table()));
    m_instancesLabel = heading(this);
    m_instances = new RowTable(QStringList(kInstanceColumnCount, QString()), this);
    m_instances->setObjectName(QStringLiteral("instanceTable"));
    m_instances->table()->setItemDelegateForColumn(int(InstanceColumn::Program),
        new ChoiceDelegate([this] { return programNames(m_projectModel.project()); }, m_instances->table()));
    m_globalsLabel = heading(this);
    m_globalLists = new QListWidget(this);
    m_globalLists->setObjectName(QStringLiteral("resourceGlobalLists"));
    m_globalLists->setMaximumHeight(m_globalLists->fontMetrics().height() * 5);
    m_addGlobalList = new QPushButton(this);
    m_otherMessages = new MessageLabel(this);

    auto *resourceRow = new QHBoxLayout;
    resourceRow->addWidget(m_resourceLabel);
    resourceRow->addWidget(m_resourceBox);
    resourceRow->addWidget(m_resourceName, 1);
    resourceRow->addWidget(m_addResource);
    resourceRow->addWidget(m_removeResource);
    auto *globalsRow = new QHBoxLayout;
    globalsRow->addWidget(m_globalLists, 1);
    globalsRow->addWidget(m_addGlobalList, 0, Qt::AlignTop);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addLayout(resourceRow);
    layout->addWidget(m_resourceMessage);
    layout->addWidget(m_tasksLabel);
    layout->addWidget(m_tasks, 3);
    layout->addWidget(m_instancesLabel);
    layout->addWidget(m_instances, 2);
    layout->addWidget(m_globalsLabel);
    layout->addLayout(globalsRow);
    layout->addWidget(m_otherMessages);

    connect(m_resourceBox, &QComboBox::activated, this, [this](int index) {
        m_resource = index;
        refreshFromModel();
    });
    connect(m_resourceName, &QLineEdit::editingFinished, this, &ConfigurationEditor::applyResourceName);
    connect(m_addResource, &QPushButton::clicked, this, &ConfigurationEditor::addResource);
    connect(m_removeResource, &QPushButton::clicked, this, &ConfigurationEditor::removeCurrentResource);
    connect(m_tasks, &RowTable::edited, this, &ConfigurationEditor::applyTasks);
    connect(m_instances, &RowTable::edited, this, &ConfigurationEditor::applyInstances);
    connect(m_tasks->table(), &QTableWidget::currentCellChanged, this, &ConfigurationEditor::showInstancesOfCurrentTask);
    connect(m_globalLists, &QListWidget::itemActivated, this, [this](QListWidgetItem *item) {
        Q_EMIT openGlobalListRequested(item->data(Qt::UserRole).value<GlobalListRef>());
    });
    connect(m_addGlobalList, &QPushButton::clicked, this, [this] {
        if (const model::Configuration *configuration = current(); configuration && m_resource < int(configuration->resources.size()))
            Q_EMIT addGlobalListRequested({configuration->name, configuration->resources[size_t(m_resource)].name, {}});
    });
    connect(&projectModel, &model::ProjectModel::instancesChanged, this, &ConfigurationEditor::refreshFromModel);
    connect(&projectModel, &model::ProjectModel::projectReset, this, &ConfigurationEditor::refreshFromModel);
    connect(&projectModel, &model::ProjectModel::pouRenamed, this, &ConfigurationEditor::refreshFromModel);
    retranslate();
    refreshFromModel();
}

void ConfigurationEditor::retranslate()
{
    m_title->setText(tr("Configuration %1").arg(m_configuration));
    m_resourceLabel->setText(tr("Resource:"));
    m_resourceName->setPlaceholderText(tr("Resource name"));
    m_addResource->setText(tr("Add Resource"));
    m_removeResource->setText(tr("Remove Resource"));
    m_tasksLabel->setText(tr("Tasks (the lower the priority number, the earlier the task runs)"));
    m_tasks->table()->setHorizontalHeaderLabels(
        {tr("Task"), tr("Interval (cyclic)"), tr("SINGLE (event variable)"), tr("Priority"), tr("Watchdog")});
    const QStringList taskTips {tr("The task's name, unique in the configuration."),
        tr("The task runs every interval (T#10ms). With neither an interval nor a SINGLE variable it runs in "
           "every cycle (CODESYS: freewheeling)."),
        tr("A global BOOL variable: the task runs once each time it becomes TRUE (CODESYS: triggered by event)."),
        tr("0 is the highest priority; tasks due in the same cycle run in the order of their priorities."),
        tr("The longest time one run of the task may take (T#50ms); empty for none. It is kept in the project "
           "for the target; the simulator does not check it.")};
    for (int column = 0; column < kTaskColumnCount; ++column)
        m_tasks->table()->horizontalHeaderItem(column)->setToolTip(taskTips[column]);
    fitTaskColumns();
    m_instances->table()->setHorizontalHeaderLabels({tr("Instance"), tr("Program")});
    m_globalsLabel->setText(tr("Global variable lists of the resource (double-click opens one)"));
    m_addGlobalList->setText(tr("Add List..."));
    showInstancesOfCurrentTask();
}

void ConfigurationEditor::fitTaskColumns()
{
    // The headers are long in every language: each column as wide as its header or its widest
    // cell; the last one (watchdog) takes the rest.
    for (int column = 0; column + 1 < kTaskColumnCount; ++column)
        m_tasks->table()->resizeColumnToContents(column);
}

void ConfigurationEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

const model::Configuration *ConfigurationEditor::current() const
{
    const model::Instances &instances = m_projectModel.project().instances;
    const int index = findConfiguration(instances, m_configuration);
    return index < 0 ? nullptr : &instances.configurations[size_t(index)];
}

int ConfigurationEditor::currentTask() const
{
    return m_tasks->table()->currentRow();
}

void ConfigurationEditor::showTask(const QString &resource, const QString &task)
{
    const model::Configuration *configuration = current();
    if (!configuration)
        return;
    for (int index = 0; index < int(configuration->resources.size()); ++index) {
        if (configuration->resources[size_t(index)].name.compare(resource, Qt::CaseInsensitive) == 0)
            m_resource = index;
    }
    refreshFromModel();
    const model::Resource *shown = m_resource < int(configuration->resources.size())
        ? &configuration->resources[size_t(m_resource)] : nullptr;
    for (int index = 0; shown && index < int(shown->tasks.size()); ++index) {
        if (shown->tasks[size_t(index)].name.compare(task, Qt::CaseInsensitive) == 0)
            m_tasks->table()->setCurrentCell(index, 0);
    }
}

void ConfigurationEditor::refreshFromModel()
{
    const model::Configuration *configuration = current();
    if (!configuration) {
        Q_EMIT configurationRemoved();
        return;
    }
    m_resource = std::clamp(m_resource, 0, std::max(0, int(configuration->resources.size()) - 1));
    m_resourceBox->clear();
    for (const model::Resource &resource : configuration->resources)
        m_resourceBox->addItem(resource.name);
    m_resourceBox->setCurrentIndex(m_resource);
    const bool hasResource = !configuration->resources.empty();
    for (QWidget *widget : std::initializer_list<QWidget *> {m_resourceName, m_removeResource, m_tasks, m_instances, m_addGlobalList})
        widget->setEnabled(hasResource);
    const int task = std::max(0, currentTask());
    m_resourceName->setText(hasResource ? configuration->resources[size_t(m_resource)].name : QString());
    m_tasks->setRows(hasResource ? tableRows(taskRows(configuration->resources[size_t(m_resource)])) : std::vector<RowTable::Row> {});
    if (m_tasks->table()->rowCount() > 0)
        m_tasks->table()->setCurrentCell(std::min(task, m_tasks->table()->rowCount() - 1), 0);
    fitTaskColumns();
    showInstancesOfCurrentTask();
    m_globalLists->clear();
    for (const GlobalListRef &list : globalLists(m_projectModel.project().instances)) {
        if (!hasResource || list.configuration.compare(configuration->name, Qt::CaseInsensitive) != 0
            || list.resource.compare(configuration->resources[size_t(m_resource)].name, Qt::CaseInsensitive) != 0)
            continue;
        auto *item = new QListWidgetItem(list.displayName(), m_globalLists);
        item->setData(Qt::UserRole, QVariant::fromValue(list));
    }
    showProblems({});
    updateNewRows();
}

void ConfigurationEditor::showInstancesOfCurrentTask()
{
    const model::Configuration *configuration = current();
    const int task = currentTask();
    const model::Resource *resource = configuration && m_resource < int(configuration->resources.size())
        ? &configuration->resources[size_t(m_resource)] : nullptr;
    const model::Task *shown = resource && task >= 0 && task < int(resource->tasks.size()) ? &resource->tasks[size_t(task)] : nullptr;
    m_instances->setRows(shown ? tableRows(instanceRows(*shown)) : std::vector<RowTable::Row> {});
    m_instances->setEnabled(shown != nullptr);
    m_instancesLabel->setText(shown ? tr("Programs run by task %1").arg(shown->name) : tr("Programs run by the task"));
    updateNewRows();
}

void ConfigurationEditor::updateNewRows()
{
    // Names for the next Add: tasks and instances are named in the whole configuration.
    QStringList tasks;
    QStringList instances;
    if (const model::Configuration *configuration = current()) {
        for (const model::Resource &resource : configuration->resources) {
            for (const model::Task &task : resource.tasks) {
                tasks << task.name;
                for (const model::PouInstance &instance : task.pouInstances)
                    instances << instance.name;
            }
        }
    }
    m_tasks->setNewRow({freeName(tasks, QStringLiteral("Task")), QStringLiteral("T#10ms"), {}, QStringLiteral("1"), {}});
    const QStringList programs = programNames(m_projectModel.project());
    const QString program = programs.value(0);
    const QString instance = program.isEmpty() || instances.contains(program, Qt::CaseInsensitive)
        ? freeName(instances, program.isEmpty() ? QStringLiteral("Instance") : program + QLatin1Char('_'))
        : program;
    m_instances->setNewRow({instance, program});
}

void ConfigurationEditor::applyTasks()
{
    const model::Configuration *configuration = current();
    if (!configuration || m_resource >= int(configuration->resources.size()))
        return;
    model::Configuration changed = *configuration;
    ResourceResult result = resourceWithTaskRows(changed.resources[size_t(m_resource)], textRows(m_tasks->rows()), m_resource);
    changed.resources[size_t(m_resource)] = std::move(result.resource);
    apply(changed, std::move(result.problems), tr("Change tasks of %1").arg(changed.resources[size_t(m_resource)].name));
}

void ConfigurationEditor::applyInstances()
{
    const model::Configuration *configuration = current();
    const int task = currentTask();
    if (!configuration || m_resource >= int(configuration->resources.size()))
        return;
    model::Configuration changed = *configuration;
    model::Resource &resource = changed.resources[size_t(m_resource)];
    if (task < 0 || task >= int(resource.tasks.size()))
        return;
    resource.tasks[size_t(task)] = taskWithInstanceRows(resource.tasks[size_t(task)], textRows(m_instances->rows()));
    apply(changed, {}, tr("Change programs of task %1").arg(resource.tasks[size_t(task)].name));
}

void ConfigurationEditor::applyResourceName()
{
    const model::Configuration *configuration = current();
    if (!configuration || m_resource >= int(configuration->resources.size()))
        return;
    const QString name = m_resourceName->text().trimmed();
    if (name == configuration->resources[size_t(m_resource)].name)
        return;
    model::Configuration changed = *configuration;
    changed.resources[size_t(m_resource)].name = name;
    apply(changed, {}, tr("Rename resource %1 to %2").arg(configuration->resources[size_t(m_resource)].name, name));
}

void ConfigurationEditor::addResource()
{
    const model::Configuration *configuration = current();
    if (!configuration)
        return;
    QStringList taken;
    for (const model::Resource &resource : configuration->resources)
        taken << resource.name;
    model::Configuration changed = *configuration;
    model::Resource resource;
    resource.name = freeName(taken, QStringLiteral("Resource"));
    changed.resources.push_back(resource);
    if (apply(changed, {}, tr("Add resource %1").arg(resource.name))) {
        m_resource = int(changed.resources.size()) - 1;
        refreshFromModel();
    }
}

void ConfigurationEditor::removeCurrentResource()
{
    const model::Configuration *configuration = current();
    if (!configuration || m_resource >= int(configuration->resources.size()))
        return;
    model::Configuration changed = *configuration;
    const QString name = changed.resources[size_t(m_resource)].name;
    changed.resources.erase(changed.resources.begin() + m_resource);
    apply(changed, {}, tr("Remove resource %1").arg(name));
}

bool ConfigurationEditor::apply(
    const model::Configuration &changed, std::vector<ConfigurationProblem> parsed, const QString &text)
{
    std::vector<ConfigurationProblem> problems = std::move(parsed);
    for (ConfigurationProblem &problem : validateConfiguration(changed, m_projectModel.project()))
        problems.push_back(std::move(problem));
    if (!problems.empty()) {
        showProblems(problems);
        return false;
    }
    model::Instances instances = m_projectModel.project().instances;
    const int index = findConfiguration(instances, m_configuration);
    if (index < 0 || !m_undoStack || instances.configurations[size_t(index)] == changed) {
        showProblems({});
        return false;
    }
    instances.configurations[size_t(index)] = changed;
    auto *command = new model::SetInstancesCommand(m_projectModel, std::move(instances));
    command->setText(text);
    m_undoStack->push(command);
    return true;
}

void ConfigurationEditor::showProblems(const std::vector<ConfigurationProblem> &problems)
{
    std::vector<RowTable::CellMessage> taskMessages;
    std::vector<RowTable::CellMessage> instanceMessages;
    QStringList resourceMessages;
    QStringList others;
    QStringList all;
    const int task = currentTask();
    for (const ConfigurationProblem &problem : problems) {
        all << problem.message;
        if (problem.resource != m_resource)
            others << tr("Resource %1: %2").arg(problem.resource + 1).arg(problem.message);
        else if (problem.task < 0)
            resourceMessages << problem.message;
        else if (problem.instance < 0)
            taskMessages.push_back({problem.task, problem.column, problem.message});
        else if (problem.task == task)
            instanceMessages.push_back({problem.instance, problem.column, problem.message});
        else
            others << tr("Task %1: %2").arg(problem.task + 1).arg(problem.message);
    }
    m_tasks->showMessages(taskMessages);
    m_instances->showMessages(instanceMessages);
    m_resourceMessage->showMessage(resourceMessages.join(QLatin1Char('\n')));
    m_otherMessages->showMessage(others.join(QLatin1Char('\n')));
    m_problemText = all.join(QLatin1Char('\n'));
}

} // namespace iec::editors
