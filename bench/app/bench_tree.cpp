// Prints how long the project tree takes to show a project of 1,000 POUs (issue: IDE shell,
// "a project with 1,000 POUs shows its tree in under 1 s"), and to rebuild after one rename.
#include "app/projecttreemodel.h"
#include "app/projecttreeview.h"
#include "model/projectmodel.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTextStream>

using namespace iec;

namespace {

model::Project generatedProject(int pouCount)
{
    model::Project project;
    constexpr model::BodyLanguage languages[] = {model::BodyLanguage::ST, model::BodyLanguage::IL,
                                                 model::BodyLanguage::LD, model::BodyLanguage::FBD,
                                                 model::BodyLanguage::SFC};
    for (int i = 0; i < pouCount; ++i) {
        model::Pou pou;
        pou.name = QStringLiteral("Pou%1").arg(i);
        pou.kind = model::PouKind(i % 3);
        pou.bodies.push_back(model::Body::withLanguage(languages[i % 5]));
        if (i % 5 == 4) {
            for (int a = 0; a < 3; ++a) {
                model::PouPart action;
                action.name = QStringLiteral("Action%1").arg(a);
                action.body = model::Body::withLanguage(model::BodyLanguage::ST);
                pou.actions.push_back(action);
            }
        }
        project.types.pous.push_back(std::move(pou));
    }
    return project;
}

} // namespace

int main(int argc, char *argv[])
{
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication application(argc, argv);
    QTextStream out(stdout);
    model::ProjectModel projectModel;
    app::ProjectTreeModel treeModel(projectModel);
    app::ProjectTreeView view;
    view.setProjectModel(&treeModel);
    view.resize(300, 800);
    view.show();
    QCoreApplication::processEvents();

    model::Project project = generatedProject(1000);
    QElapsedTimer timer;
    timer.start();
    projectModel.reset(std::move(project));
    view.expandAll();
    view.grab(); // forces layout and paint of the visible rows
    const double showMs = double(timer.nsecsElapsed()) / 1e6;

    timer.restart();
    projectModel.renamePou(projectModel.project().types.pous[500].id, QStringLiteral("Renamed"));
    view.grab();
    const double renameMs = double(timer.nsecsElapsed()) / 1e6;

    out << "project tree, 1000 POUs (" << treeModel.rowCount(treeModel.index(0, 0)) << " programs), all expanded\n"
        << "  show (reset + expand all + paint): " << showMs << " ms\n"
        << "  rebuild after one rename + paint:  " << renameMs << " ms\n";
    return 0;
}
